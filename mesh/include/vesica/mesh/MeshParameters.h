#pragma once
// vesica-mesh's parameter table: every option of the command line and every `params` key
// of a mesh stage in a pipeline file, with unit, range, help and the default of the
// library struct it is bound to. Depends only on core (and header-only settings), so the
// runner links it to check pipeline files before any stage runs.
#include "vesica/core/ParameterTable.h"
#include "vesica/mesh/CavityMesher.h"
#include "vesica/mesh/MembraneFields.h"

namespace vesica::mesh {

// What the table fills.
struct MeshSettings {
  bool fluid = false;            // also mesh the urine with tetrahedra
  MembraneOptions membrane;      // thickness, per-region thickness, fiber direction
  bool fiber_long_axis = false;  // fibers along the wall's long axis (found once it is read)
  CavityOptions cavity;          // largest tetrahedron and grading
};

ParameterTable parameter_table(MeshSettings& settings);
// Bound to default settings of its own (the runner's copy).
ParameterTable parameter_table();

}  // namespace vesica::mesh
