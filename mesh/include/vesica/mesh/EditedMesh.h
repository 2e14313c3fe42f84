#pragma once
// A mesh file edited in Gmsh: Gmsh keeps the mesh and its physical groups when it saves an
// edit, but not the element data (views) vesica-mesh wrote, so the wall's thickness and
// fibers must be computed again, as for a new mesh, and the user told which ones were.
#include <string>
#include <vector>

#include "vesica/mesh/MembraneFields.h"
#include "vesica/mesh/VolumeMesh.h"

namespace vesica::mesh {

// Fills in the thickness and fibers `mesh` lacks as membrane_fields computes them; returns
// what it filled in, such as "thickness_mm (3 mm everywhere)" and "fiber1, fiber2", for the
// warning that says so (empty when the file had them all).
std::vector<std::string> complete_membrane_fields(VolumeMesh& mesh, const MembraneOptions& options);

}  // namespace vesica::mesh
