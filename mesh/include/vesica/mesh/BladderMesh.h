#pragma once
// The mesh stage as one call: a checked surface becomes membrane elements and, when
// asked, the conforming tetrahedra of the urine.
#include <optional>
#include <string>

#include "vesica/mesh/CavityMesher.h"
#include "vesica/mesh/MembraneFields.h"
#include "vesica/mesh/SurfaceMesh.h"
#include "vesica/mesh/VolumeMesh.h"

namespace vesica::mesh {

// Checks the surface (require_valid_surface), turns it outward if it was inward, and
// meshes the cavity when `cavity` is given. `origin` names the input in errors.
VolumeMesh build_bladder_mesh(SurfaceMesh surface, const MembraneOptions& membrane,
                              const std::optional<CavityOptions>& cavity,
                              const std::string& origin);

}  // namespace vesica::mesh
