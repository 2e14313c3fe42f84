// Isochoric neo-Hookean matrix (docs/physics.md §2): S_iso = μ J^(-2/3)(I - (1/3) tr(C) C⁻¹).
#include "materials/DecoupledParts.h"

namespace vesica::simulate {

void NeoHookeanIsochoric::S_iso(const Kinematics& k, const MaterialPoint& /*point*/,
                                Eigen::Matrix3d& S, Voigt6& D) const {
  const IsochoricInvariant I1 = isochoric_invariant(k, Eigen::Matrix3d::Identity());
  S = mu_ * I1.d_dC;
  D = 2.0 * mu_ * I1.d2_dC2;
}

}  // namespace vesica::simulate
