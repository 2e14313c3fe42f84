#include "vesica/mesh/EditedMesh.h"

#include <fmt/format.h>

namespace vesica::mesh {

std::vector<std::string> complete_membrane_fields(VolumeMesh& mesh,
                                                  const MembraneOptions& options) {
  const Eigen::Index m = mesh.triangles.rows();
  const bool has_thickness = mesh.thickness_mm.size() == m;
  const bool has_fibers = mesh.fiber1.rows() == m && mesh.fiber2.rows() == m;
  if (has_thickness && has_fibers) return {};
  const MembraneFields fields =
      membrane_fields(SurfaceMesh{mesh.nodes, mesh.triangles, mesh.tri_region}, options);
  std::vector<std::string> filled;
  if (!has_thickness) {
    mesh.thickness_mm = fields.thickness_mm;
    filled.push_back(fmt::format("thickness_mm ({:g} mm everywhere)", options.thickness_mm));
  }
  if (!has_fibers) {
    mesh.fiber1 = fields.fiber1;
    mesh.fiber2 = fields.fiber2;
    filled.emplace_back("fiber1, fiber2");
  }
  return filled;
}

}  // namespace vesica::mesh
