#include "wall/WallSurroundings.h"

#include "vesica/core/Units.h"

namespace vesica::simulate {

Eigen::Vector3d protocol_gravity(const ProtocolSettings& settings) {
  return settings.gravity ? gravity_lps(settings.posture) : Eigen::Vector3d::Zero();
}

WallLoads surroundings(const ProtocolSettings& settings, const Eigen::Vector3d& gravity,
                       const Eigen::Vector3d& x_ref) {
  WallLoads loads;
  // The abdomen is a fluid too: its hydrostatic gradient acts on the outer face.
  loads.outside.rho = settings.abdominal_density;
  loads.outside.gravity = gravity;
  loads.outside.x_ref = x_ref;
  if (settings.wall_weight) loads.wall_gravity = gravity;
  loads.wall_density = settings.wall_density;
  // kPa per mm of displacement → Pa/m.
  loads.support_stiffness = units::pa_from_kpa(settings.support_kpa_per_mm) / units::m_from_mm(1.0);
  return loads;
}

}  // namespace vesica::simulate
