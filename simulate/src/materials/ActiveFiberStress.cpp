// Active detrusor fiber stress S_a = T_a(t) A / Ī4 along both families (docs/physics.md §2).
#include "materials/DecoupledParts.h"

namespace vesica::simulate {

void add_active_fiber_stress(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
                             Voigt6& D) {
  const double Ta = point.active_stress_pa;
  if (Ta == 0.0) return;
  for (const Eigen::Vector3d& a0 : point.fibers) {
    const Eigen::Matrix3d A = a0 * a0.transpose();
    const IsochoricInvariant I4 = isochoric_invariant(k, A);
    S += Ta / I4.value * A;
    D += -2.0 * Ta / (I4.value * I4.value) * outer(A, I4.d_dC);
  }
}

}  // namespace vesica::simulate
