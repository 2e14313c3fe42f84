#include "vesica/simulate/wall/WallModel.h"

#include <cmath>
#include <map>
#include <utility>

#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {

double enclosed_volume(const WallModel& wall, const std::vector<Eigen::Vector3d>& x) {
  double V = 0.0;
  for (const auto& t : wall.triangles) V += x[t[0]].dot(x[t[1]].cross(x[t[2]]));
  return V / 6.0;
}

Eigen::Vector3d surface_centroid(const WallModel& wall) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (const auto& t : wall.triangles) {
    const Eigen::Vector3d &a = wall.nodes[t[0]], &b = wall.nodes[t[1]], &d = wall.nodes[t[2]];
    const double A = 0.5 * (b - a).cross(d - a).norm();
    c += A * (a + b + d) / 3.0;
    area += A;
  }
  return c / area;
}

Eigen::Vector3d pressure_reference_point(const WallModel& wall, const Eigen::Vector3d& g) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  int count = 0;
  for (std::size_t e = 0; e < wall.triangle_count(); ++e)
    if (wall.region[e] == static_cast<int>(Region::Outlet))
      for (int n : wall.triangles[e]) sum += wall.nodes[n], ++count;
  if (count > 0) return sum / count;
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < wall.node_count(); ++i)
    if (wall.nodes[i].dot(g) > wall.nodes[lowest].dot(g)) lowest = i;
  return g.norm() > 0.0 ? wall.nodes[lowest] : surface_centroid(wall);
}

std::size_t fix_regions(WallModel& wall, const Eigen::Vector3d& down, double patch_radius_m) {
  wall.fixed.assign(wall.nodes.size(), {false, false, false});
  wall.support.assign(wall.nodes.size(), false);
  for (std::size_t e = 0; e < wall.triangles.size(); ++e) {
    const auto r = static_cast<Region>(wall.region[e]);
    for (int n : wall.triangles[e]) {
      if (r == Region::Outlet || r == Region::Inlet || r == Region::Fixed)
        wall.fixed[n] = {true, true, true};
      if (r == Region::Support) wall.support[n] = true;
    }
  }
  std::size_t count = 0;
  for (const auto& f : wall.fixed) count += f[0] ? 1 : 0;
  if (count > 0) return count;
  // Nothing held: pin a small patch around the lowest point (the bladder base).
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < wall.nodes.size(); ++i)
    if (wall.nodes[i].dot(down) > wall.nodes[lowest].dot(down)) lowest = i;
  for (const auto& t : wall.triangles)  // at least the triangles around the lowest node
    for (int n : t)
      if (n == static_cast<int>(lowest))
        for (int m : t) wall.fixed[m] = {true, true, true};
  for (std::size_t i = 0; i < wall.nodes.size(); ++i)
    if ((wall.nodes[i] - wall.nodes[lowest]).norm() <= patch_radius_m)
      wall.fixed[i] = {true, true, true};
  for (const auto& f : wall.fixed) count += f[0] ? 1 : 0;
  return count;
}

void scale_to_volume(WallModel& wall, double volume_m3) {
  const double V = enclosed_volume(wall, wall.nodes);
  const double s = std::cbrt(volume_m3 / V);
  const Eigen::Vector3d c = surface_centroid(wall);
  for (auto& p : wall.nodes) p = c + s * (p - c);
}

void check_closed_surface(const WallModel& wall, const std::string& source) {
  if (wall.triangles.empty())
    fail(source, "has no triangles", "give the wall surface or the .vtu from vesica-mesh");
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : wall.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
  for (const auto& [edge, n] : directed) {
    const auto back = directed.find({edge.second, edge.first});
    if (n != 1 || back == directed.end() || back->second != 1)
      fail(source,
           "wall surface is not closed, manifold and consistently oriented (edge " +
               std::to_string(edge.first) + "-" + std::to_string(edge.second) + ")",
           "close openings with outlet/inlet caps (vesica-surface does this)");
  }
  if (!(enclosed_volume(wall, wall.nodes) > 0.0))
    fail(source, "wall surface encloses no volume or is oriented inward",
         "orient the triangles with outward normals");
}

}  // namespace vesica::simulate
