// Matrix + two exponential fiber families, tension only (docs/physics.md §2).
#include <cmath>

#include "materials/DecoupledParts.h"

namespace vesica::simulate {

void FiberFamilies::S_iso(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
                          Voigt6& D) const {
  matrix_.S_iso(k, point, S, D);
  for (const Eigen::Vector3d& a0 : point.fibers) {
    const Eigen::Matrix3d A = a0 * a0.transpose();
    const IsochoricInvariant I4 = isochoric_invariant(k, A);
    const double e = I4.value - 1.0;
    if (e <= 0.0) continue;  // a fiber under compression carries nothing
    const double ex = std::exp(k2_ * e * e);
    const double dpsi = k1_ * e * ex;                           // ψ'
    const double d2psi = k1_ * ex * (1.0 + 2.0 * k2_ * e * e);  // ψ''
    S += 2.0 * dpsi * I4.d_dC;
    D += 4.0 * d2psi * outer(I4.d_dC, I4.d_dC) + 4.0 * dpsi * I4.d2_dC2;
  }
}

}  // namespace vesica::simulate
