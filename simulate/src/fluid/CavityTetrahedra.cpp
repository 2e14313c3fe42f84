#include "fluid/CavityTetrahedra.h"

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

}  // namespace vesica::simulate::fluid
