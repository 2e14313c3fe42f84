#pragma once
// Backward-displacement (prestress) recovery of the stress-free wall (issue 7 (b)): the
// imaged bladder is in equilibrium at a known pressure, so find the reference X whose
// loaded state x(X) is the imaged geometry, by the fixed-point update
//   X_k+1 = X_k + (x_imaged - x(X_k)).
#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// pressure_pa: transmural pressure at imaging. Throws vesica::Error when the pressure
// exceeds what the wall can carry or the iteration does not converge.
WallModel prestressed_reference(const WallModel& imaged, const Material& material,
                                double pressure_pa, int threads = 2);

}  // namespace vesica::simulate
