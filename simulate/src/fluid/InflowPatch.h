#pragma once
// Inflow at a prescribed volume rate through a patch of boundary faces (a ureter inlet):
// a plug profile along the inward node normals, zero on the patch's rim nodes that the
// wall holds, scaled so that the discrete flux −∫ u·n dA of the P1 field is exactly Q.
#include <array>
#include <vector>

#include "fluid/BoundaryFaces.h"
#include "fluid/FluidBoundary.h"

namespace vesica::simulate::fluid {

// patch: boundary faces (any orientation); held[i]: node i keeps its own (wall) velocity
// condition and gets none here; flow_rate in m³/s (into the fluid). Throws
// std::invalid_argument when the patch has no free node.
std::vector<VelocityCondition> plug_inflow(const BoundaryFaces& boundary,
                                           const std::vector<std::array<int, 3>>& patch,
                                           const std::vector<bool>& held, double flow_rate);

}  // namespace vesica::simulate::fluid
