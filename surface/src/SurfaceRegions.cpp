#include "vesica/surface/SurfaceRegions.h"

#include <functional>
#include <limits>
#include <queue>
#include <sstream>
#include <utility>

#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"

namespace vesica::surface {

namespace {

int nearest_vertex(const Eigen::MatrixXd& V, const Eigen::Vector3d& p, double max_distance,
                   const char* what) {
  Eigen::Index best = 0;
  const double d2 = (V.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&best);
  if (std::sqrt(d2) > max_distance) {
    std::ostringstream problem;
    problem << what << " landmark (" << p.x() << "," << p.y() << "," << p.z() << ") is "
            << std::sqrt(d2) << " mm from the surface";
    usage_error(problem.str(), "landmarks are LPS millimetres on the bladder wall");
  }
  return static_cast<int>(best);
}

int most_inferior_vertex(const Eigen::MatrixXd& V) {
  Eigen::Index best = 0;
  V.col(2).minCoeff(&best);  // LPS: +z is superior
  return static_cast<int>(best);
}

// Tags triangles whose mean corner distance is within radius, plus the source's own fan,
// so that a patch is never empty. Only triangles still tagged below `tag` are changed.
void tag_geodesic_patch(const Eigen::MatrixXi& F, const Eigen::VectorXd& distance, int source,
                        double radius, int tag, Eigen::VectorXi& region,
                        const std::function<bool(int)>& may_overwrite) {
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const double mean = (distance(F(f, 0)) + distance(F(f, 1)) + distance(F(f, 2))) / 3.0;
    const bool touches = F(f, 0) == source || F(f, 1) == source || F(f, 2) == source;
    if ((mean <= radius || touches) && may_overwrite(region(f))) region(f) = tag;
  }
}

}  // namespace

Eigen::VectorXd edge_path_distances(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F,
                                    int source) {
  std::vector<std::vector<std::pair<int, double>>> neighbours(V.rows());
  for (Eigen::Index f = 0; f < F.rows(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = F(f, k), b = F(f, (k + 1) % 3);
      const double length = (V.row(a) - V.row(b)).norm();
      neighbours[a].emplace_back(b, length);
      neighbours[b].emplace_back(a, length);
    }
  Eigen::VectorXd distance =
      Eigen::VectorXd::Constant(V.rows(), std::numeric_limits<double>::infinity());
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  distance(source) = 0.0;
  queue.emplace(0.0, source);
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > distance(v)) continue;
    for (const auto& [w, length] : neighbours[v])
      if (d + length < distance(w)) {
        distance(w) = d + length;
        queue.emplace(distance(w), w);
      }
  }
  return distance;
}

RegionSummary assign_regions(const RegionOptions& options, TriangleSurface& surface) {
  const auto& V = surface.V;
  const auto& F = surface.F;
  const int wall = static_cast<int>(Region::Wall), outlet = static_cast<int>(Region::Outlet),
            inlet = static_cast<int>(Region::Inlet), fixed = static_cast<int>(Region::Fixed),
            support = static_cast<int>(Region::Support);
  surface.region = Eigen::VectorXi::Constant(F.rows(), wall);
  const int outlet_vertex =
      options.outlet
          ? nearest_vertex(V, *options.outlet, options.max_landmark_distance_mm, "outlet")
          : most_inferior_vertex(V);
  const Eigen::VectorXd from_outlet = edge_path_distances(V, F, outlet_vertex);
  const double outlet_z = V(outlet_vertex, 2);
  auto centroid_height = [&](Eigen::Index f) {
    return (V(F(f, 0), 2) + V(F(f, 1), 2) + V(F(f, 2), 2)) / 3.0 - outlet_z;
  };

  // Lowest priority first; each later tag overwrites the earlier ones.
  if (options.support_below_mm > 0)
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      if (centroid_height(f) <= options.support_below_mm) surface.region(f) = support;
  if (options.fixed_below_mm > 0)
    for (Eigen::Index f = 0; f < F.rows(); ++f)
      if (centroid_height(f) <= options.fixed_below_mm) surface.region(f) = fixed;
  const auto any = [](int) { return true; };
  if (options.fixed_radius_mm > 0)
    tag_geodesic_patch(F, from_outlet, outlet_vertex, options.fixed_radius_mm, fixed,
                       surface.region, any);
  for (const Eigen::Vector3d& landmark : options.inlets) {
    const int v = nearest_vertex(V, landmark, options.max_landmark_distance_mm, "inlet");
    tag_geodesic_patch(F, edge_path_distances(V, F, v), v, options.inlet_radius_mm, inlet,
                       surface.region, any);
  }
  tag_geodesic_patch(F, from_outlet, outlet_vertex, options.outlet_radius_mm, outlet,
                     surface.region, any);

  RegionSummary summary;
  summary.outlet_mm = V.row(outlet_vertex).transpose();
  summary.triangle_counts.assign(6, 0);
  for (Eigen::Index f = 0; f < F.rows(); ++f) ++summary.triangle_counts[surface.region(f)];
  return summary;
}

}  // namespace vesica::surface
