#include "fluid/CavityTetrahedra.h"

#include <cmath>
#include <stdexcept>

#include "vesica/mesh/CavityMesher.h"

namespace vesica::simulate::fluid {

FluidMesh cavity_tetrahedra(const WallModel& wall, const std::vector<Eigen::Vector3d>& x_wall,
                            double max_size_mm) {
  const auto n_wall = static_cast<Eigen::Index>(wall.node_count());
  if (static_cast<Eigen::Index>(x_wall.size()) != n_wall)
    throw std::invalid_argument("cavity_tetrahedra: one position per wall node");
  // vesica-mesh works in mm.
  vesica::mesh::SurfaceMesh surface;
  surface.points.resize(n_wall, 3);
  for (Eigen::Index i = 0; i < n_wall; ++i) surface.points.row(i) = 1e3 * x_wall[i].transpose();
  const auto n_tri = static_cast<Eigen::Index>(wall.triangle_count());
  surface.triangles.resize(n_tri, 3);
  surface.region.resize(n_tri);
  for (Eigen::Index t = 0; t < n_tri; ++t) {
    for (int k = 0; k < 3; ++k) surface.triangles(t, k) = wall.triangles[t][k];
    surface.region[t] = wall.region.empty() ? 1 : wall.region[t];
  }
  vesica::mesh::CavityOptions options;
  options.max_size_mm = max_size_mm;
  const auto cavity = vesica::mesh::mesh_cavity(surface, options, "urine remeshing");
  FluidMesh mesh;
  mesh.nodes.reserve(cavity.nodes.rows());
  for (Eigen::Index i = 0; i < cavity.nodes.rows(); ++i)
    mesh.nodes.push_back(1e-3 * cavity.nodes.row(i).transpose());
  // mesh_cavity keeps the wall nodes (it checks): undo the round-off of m -> mm -> m so
  // that the wall and the urine share their nodes exactly.
  for (Eigen::Index i = 0; i < n_wall; ++i) mesh.nodes[i] = x_wall[i];
  mesh.tets.reserve(cavity.tets.rows());
  for (Eigen::Index t = 0; t < cavity.tets.rows(); ++t)
    mesh.tets.push_back(
        {cavity.tets(t, 0), cavity.tets(t, 1), cavity.tets(t, 2), cavity.tets(t, 3)});
  return mesh;
}

namespace {

// gmsh runs of one size search at most.
constexpr int kSizeSearchRuns = 4;
// log(count) against log(size) before two sizes give a secant: the size field's grading
// from the wall's own edges makes the count fall more slowly than size⁻³.
constexpr double kFirstSlope = -2.0;

double mean_wall_edge_mm(const WallModel& wall, const std::vector<Eigen::Vector3d>& x_wall) {
  double sum = 0.0;
  for (const auto& t : wall.triangles)
    for (int k = 0; k < 3; ++k) sum += (x_wall[t[k]] - x_wall[t[(k + 1) % 3]]).norm();
  return 1e3 * sum / (3.0 * static_cast<double>(wall.triangle_count()));
}

}  // namespace

FluidMesh cavity_tetrahedra_of_count(const WallModel& wall,
                                     const std::vector<Eigen::Vector3d>& x_wall, std::size_t target,
                                     double tolerance, double& size_mm) {
  double size = size_mm > 0.0 ? size_mm : mean_wall_edge_mm(wall, x_wall);
  FluidMesh best;
  double best_error = INFINITY, slope = kFirstSlope;
  double last_log_size = 0.0, last_log_count = 0.0;
  for (int run = 0; run < kSizeSearchRuns; ++run) {
    FluidMesh mesh = cavity_tetrahedra(wall, x_wall, size);
    const double log_count = std::log(static_cast<double>(mesh.tets.size()));
    const double log_ratio = log_count - std::log(static_cast<double>(target));
    const double error = std::abs(std::expm1(log_ratio));
    if (error < best_error) {
      best_error = error;
      best = std::move(mesh);
      size_mm = size;
    }
    if (error <= tolerance) break;
    if (run > 0 && std::abs(std::log(size) - last_log_size) > 1e-12) {
      const double secant = (log_count - last_log_count) / (std::log(size) - last_log_size);
      if (secant < -0.1) slope = secant;  // the count must fall as the size grows
    }
    last_log_size = std::log(size);
    last_log_count = log_count;
    size *= std::exp(-log_ratio / slope);
  }
  return best;
}

}  // namespace vesica::simulate::fluid
