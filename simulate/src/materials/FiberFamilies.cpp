// Matrix + two exponential fiber families on the full I4, tension only (docs/physics.md §2.4).
#include <cmath>

#include "materials/DecoupledParts.h"

namespace vesica::simulate {

void FiberFamilies::S_iso(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
                          Voigt6& D) const {
  matrix_.S_iso(k, point, S, D);
  for (const Eigen::Vector3d& a0 : point.fibers) {
    const double e = a0.dot(k.C * a0) - 1.0;  // I4 - 1
    if (e <= 0.0) continue;                   // a fiber under compression carries nothing
    const double ex = std::exp(k2_ * e * e);
    const double dpsi = k1_ * e * ex;                           // ψ'
    const double d2psi = k1_ * ex * (1.0 + 2.0 * k2_ * e * e);  // ψ''
    const Eigen::Matrix3d A = a0 * a0.transpose();              // dI4/dC
    S += 2.0 * dpsi * A;
    D += 4.0 * d2psi * outer(A, A);
  }
}

}  // namespace vesica::simulate
