#include "vesica/simulate/wall/SphereMesh.h"

#include <map>
#include <tuple>

namespace vesica::simulate {

WallModel sphere_wall(double radius, double thickness, int n) {
  WallModel wall;
  const Eigen::Vector3d axes[6] = {Eigen::Vector3d::UnitX(), -Eigen::Vector3d::UnitX(),
                                   Eigen::Vector3d::UnitY(), -Eigen::Vector3d::UnitY(),
                                   Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};
  std::map<std::tuple<long, long, long>, int> index;  // dedupe shared edge points
  auto node = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = p.normalized() * radius;
    const auto key =
        std::make_tuple(std::lround(q.x() / radius * 1e9), std::lround(q.y() / radius * 1e9),
                        std::lround(q.z() / radius * 1e9));
    const auto it = index.find(key);
    if (it != index.end()) return it->second;
    wall.nodes.push_back(q);
    return index[key] = static_cast<int>(wall.nodes.size()) - 1;
  };
  for (int sx : {0, 1})
    for (int sy : {2, 3})
      for (int sz : {4, 5}) {
        Eigen::Vector3d A = axes[sx], B = axes[sy], C = axes[sz];
        if (A.dot(B.cross(C)) < 0) std::swap(B, C);  // outward orientation
        auto point = [&](int i, int j) {  // barycentric grid point (i along B, j along C)
          return (A * (n - i - j) + B * i + C * j) / double(n);
        };
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n - i; ++j) {
            wall.triangles.push_back(
                {node(point(i, j)), node(point(i + 1, j)), node(point(i, j + 1))});
            if (i + j < n - 1)
              wall.triangles.push_back(
                  {node(point(i + 1, j)), node(point(i + 1, j + 1)), node(point(i, j + 1))});
          }
      }
  wall.region.assign(wall.triangles.size(), 1);
  wall.thickness.assign(wall.triangles.size(), thickness);
  wall.fixed.assign(wall.nodes.size(), {false, false, false});
  wall.support.assign(wall.nodes.size(), false);
  return wall;
}

void fix_sphere_rigid_modes(WallModel& wall) {
  double R = wall.nodes[0].norm();
  auto find = [&](const Eigen::Vector3d& p) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < wall.nodes.size(); ++i)
      if ((wall.nodes[i] - p).norm() < (wall.nodes[best] - p).norm()) best = i;
    return best;
  };
  const std::size_t top = find({0, 0, R}), bottom = find({0, 0, -R}), east = find({R, 0, 0});
  wall.fixed[top][0] = wall.fixed[top][1] = true;
  wall.fixed[bottom][0] = wall.fixed[bottom][1] = true;
  wall.fixed[east][1] = wall.fixed[east][2] = true;
}

}  // namespace vesica::simulate
