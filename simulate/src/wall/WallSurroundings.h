#pragma once
// What surrounds the wall in every cavity model (docs/physics.md §4): gravity, the abdomen
// as a fluid pressing on the outer face (its hydrostatic gradient about the urine's
// reference point), the wall's own weight and the springs of the support region. SI.
#include <Eigen/Dense>

#include "vesica/simulate/protocol/CystometrySettings.h"
#include "wall/MembraneProblem.h"

namespace vesica::simulate {

// g in LPS patient coordinates (m/s²), zero without gravity.
Eigen::Vector3d protocol_gravity(const ProtocolSettings& settings);

// The wall's loads from its surroundings: the abdomen outside (outside.p0 = 0 until the
// protocol's loads set it), the wall weight, the support springs. x_ref: the reference
// point of the urine pressure (pressure_reference_point), shared by the abdomen.
WallLoads surroundings(const ProtocolSettings& settings, const Eigen::Vector3d& gravity,
                       const Eigen::Vector3d& x_ref);

}  // namespace vesica::simulate
