#include "vesica/surface/TriangleSurface.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "vesica/core/Regions.h"

namespace vesica::surface {

namespace {
Eigen::Vector3d corner(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F, Eigen::Index f, int k) {
  return V.row(F(f, k)).transpose();
}
}  // namespace

Eigen::VectorXi TriangleSurface::regions_or_wall() const {
  if (region.size() == F.rows()) return region;
  return Eigen::VectorXi::Constant(F.rows(), static_cast<int>(Region::Wall));
}

double enclosed_volume(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  // Tetrahedra from a reference point near the surface keep the sum well conditioned
  // for surfaces far from the origin (patient coordinates can be hundreds of mm away).
  const Eigen::Vector3d o =
      V.rows() ? Eigen::Vector3d(V.colwise().mean().transpose()) : Eigen::Vector3d::Zero();
  double six_v = 0.0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    six_v += (corner(V, F, f, 0) - o).dot((corner(V, F, f, 1) - o).cross(corner(V, F, f, 2) - o));
  return six_v / 6.0;
}

double surface_area(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  double area = 0.0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    area += 0.5 * (corner(V, F, f, 1) - corner(V, F, f, 0))
                      .cross(corner(V, F, f, 2) - corner(V, F, f, 0))
                      .norm();
  return area;
}

Eigen::Vector3d volume_centroid(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  const Eigen::Vector3d o = V.colwise().mean().transpose();
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();
  double six_v = 0.0;
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const Eigen::Vector3d a = corner(V, F, f, 0) - o, b = corner(V, F, f, 1) - o,
                          c = corner(V, F, f, 2) - o;
    const double w = a.dot(b.cross(c));
    six_v += w;
    moment += w * (a + b + c) / 4.0;  // centroid of tetrahedron (o, a, b, c) relative to o
  }
  return std::abs(six_v) > 0 ? Eigen::Vector3d(o + moment / six_v) : o;
}

Eigen::VectorXd triangle_min_angles_deg(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  Eigen::VectorXd angles(F.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    double smallest = 180.0;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d u = corner(V, F, f, (k + 1) % 3) - corner(V, F, f, k);
      const Eigen::Vector3d w = corner(V, F, f, (k + 2) % 3) - corner(V, F, f, k);
      const double a = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
      smallest = std::min(smallest, a);
    }
    angles(f) = smallest;
  }
  return angles;
}

double mean_edge_length(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F) {
  double sum = 0.0;
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) sum += (corner(V, F, f, (k + 1) % 3) - corner(V, F, f, k)).norm();
  return F.rows() ? sum / (3.0 * F.rows()) : 0.0;
}

double rescale_to_volume(double target_mm3, TriangleSurface& surface) {
  const double volume = enclosed_volume(surface.V, surface.F);
  if (!(volume > 0) || !(target_mm3 > 0)) return 1.0;
  const double s = std::cbrt(target_mm3 / volume);
  const Eigen::RowVector3d c = volume_centroid(surface.V, surface.F).transpose();
  surface.V = ((surface.V.rowwise() - c) * s).rowwise() + c;
  return s;
}

}  // namespace vesica::surface
