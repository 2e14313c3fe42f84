#include "vesica/mesh/BladderMesh.h"

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/mesh/SurfaceDefects.h"

namespace vesica::mesh {

VolumeMesh build_bladder_mesh(SurfaceMesh surface, const MembraneOptions& membrane,
                              const std::optional<CavityOptions>& cavity,
                              const std::string& origin) {
  require_valid_surface(surface, origin);
  if (enclosed_volume_mm3(surface) < 0.0) {
    log()->info("{}: triangles point inwards; reversing them", origin);
    flip_orientation(surface);
  }
  const MembraneFields fields = membrane_fields(surface, membrane);
  VolumeMesh mesh;
  mesh.triangles = surface.triangles;
  mesh.tri_region = surface.region;
  mesh.thickness_mm = fields.thickness_mm;
  mesh.fiber1 = fields.fiber1;
  mesh.fiber2 = fields.fiber2;
  if (cavity) {
    CavityMesh fluid = mesh_cavity(surface, *cavity, origin);
    mesh.nodes = std::move(fluid.nodes);
    mesh.tets = std::move(fluid.tets);
  } else {
    mesh.nodes = surface.points;
    mesh.tets.resize(0, 4);
  }
  return mesh;
}

}  // namespace vesica::mesh
