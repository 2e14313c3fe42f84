// Ogden volumetric term and the shared decoupled kinematics (docs/physics.md §2).
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

double OgdenVolumetric::dPsi_vol_dJ(double J) const {
  return K_ / beta_ * (1.0 - std::pow(J, -beta_)) / J;
}

void OgdenVolumetric::S_vol(const Kinematics& k, Eigen::Matrix3d& S, Voigt6& D) const {
  const double J_mb = std::pow(k.J, -beta_);
  const double f = K_ / beta_ * (1.0 - J_mb);  // J dΨ_vol/dJ
  S = f * k.C_inv;
  D = K_ * J_mb * outer(k.C_inv, k.C_inv) - 2.0 * f * odot(k.C_inv);
}

}  // namespace vesica::simulate
