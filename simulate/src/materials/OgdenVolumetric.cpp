// Ogden volumetric term (with its β → 0 limit K/2 (ln J)²) and the shared decoupled
// kinematics (docs/physics.md §2).
#include <cmath>

#include "materials/DecoupledParts.h"

namespace vesica::simulate {

Kinematics::Kinematics(const Eigen::Matrix3d& C_) : C(C_) {
  C_inv = C.inverse();
  J = std::sqrt(C.determinant());
  J_m23 = 1.0 / std::cbrt(J * J);  // J^(-2/3); cbrt is several times cheaper than pow
}

IsochoricInvariant isochoric_invariant(const Kinematics& k, const Eigen::Matrix3d& M) {
  IsochoricInvariant inv;
  inv.value = k.J_m23 * (k.C.cwiseProduct(M)).sum();
  inv.d_dC = k.J_m23 * M - inv.value / 3.0 * k.C_inv;
  // The three outer products as one symmetric pair: with a = dĪ/3 + Ī C⁻¹/18,
  // (dĪ ⊗ C⁻¹ + C⁻¹ ⊗ dĪ)/3 + Ī/9 C⁻¹ ⊗ C⁻¹ = a ⊗ C⁻¹ + C⁻¹ ⊗ a.
  const Vector6 c = to_voigt(k.C_inv);
  const Vector6 a = to_voigt(inv.d_dC) / 3.0 + inv.value / 18.0 * c;
  inv.d2_dC2.noalias() = -(a * c.transpose());
  inv.d2_dC2.noalias() -= c * a.transpose();
  inv.d2_dC2 += inv.value / 3.0 * odot(k.C_inv);
  return inv;
}

// J dΨ_vol/dJ = (K/β)(1 − J^(−β)) = −(K/β) expm1(−β ln J): the difference 1 − J^(−β) of two
// numbers near 1 loses every digit below ε/(β ln J), so for β of 1e-3–1e-4 the stress had
// no digits left for Newton's last iterations; expm1 keeps them. β = 0 is its limit,
// K ln J: the volumetric law K/2 (ln J)² (docs/physics.md §2.3).
double OgdenVolumetric::J_dPsi_dJ(double log_J) const {
  return beta_ == 0.0 ? K_ * log_J : -K_ / beta_ * std::expm1(-beta_ * log_J);
}

double OgdenVolumetric::dPsi_vol_dJ(double J) const {
  return J_dPsi_dJ(std::log(J)) / J;
}

void OgdenVolumetric::S_vol(const Kinematics& k, Eigen::Matrix3d& S, Voigt6& D) const {
  const double log_J = std::log(k.J);
  const double f = J_dPsi_dJ(log_J);
  S = f * k.C_inv;
  // J d(J dΨ/dJ)/dJ = K J^(−β) (K at β = 0).
  D = K_ * std::exp(-beta_ * log_J) * outer(k.C_inv, k.C_inv) - 2.0 * f * odot(k.C_inv);
}

}  // namespace vesica::simulate
