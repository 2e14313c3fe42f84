#include "fluid/TetQuality.h"

#include <algorithm>
#include <cmath>

namespace vesica::simulate::fluid {

double radius_ratio(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    const Eigen::Vector3d& d) {
  const Eigen::Vector3d u = b - a, v = c - a, w = d - a;
  const double six_volume = u.dot(v.cross(w));
  if (six_volume == 0.0) return 0.0;
  // Inradius 3V / (sum of face areas); circumradius |u²(v×w) + v²(w×u) + w²(u×v)| / 12V.
  const double faces = 0.5 * (u.cross(v).norm() + v.cross(w).norm() + w.cross(u).norm() +
                              (c - b).cross(d - b).norm());
  const double r_in = 0.5 * std::abs(six_volume) / faces;
  const double r_circ =
      (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u) + w.squaredNorm() * u.cross(v))
          .norm() /
      (2.0 * std::abs(six_volume));
  return std::copysign(3.0 * r_in / r_circ, six_volume);
}

double min_radius_ratio(const std::vector<Eigen::Vector3d>& x,
                        const std::vector<Eigen::Vector3d>& x_reference,
                        const std::vector<std::array<int, 4>>& tets) {
  double worst = 1.0;
  for (const auto& t : tets) {
    const double now = radius_ratio(x[t[0]], x[t[1]], x[t[2]], x[t[3]]);
    const double before =
        radius_ratio(x_reference[t[0]], x_reference[t[1]], x_reference[t[2]], x_reference[t[3]]);
    worst = std::min(worst, before < 0.0 ? -now : now);
  }
  return worst;
}

}  // namespace vesica::simulate::fluid
