#pragma once
// Building blocks of the decoupled (isochoric + volumetric) materials of docs/physics.md §2:
// C̄ = J^(-2/3) C, and every isochoric energy written through invariants Ī = C̄ : M.
#include <memory>

#include <Eigen/Dense>

#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/materials/Voigt.h"

namespace vesica::simulate {

// C with what every decoupled law needs of it.
struct Kinematics {
  Eigen::Matrix3d C;
  Eigen::Matrix3d C_inv;
  double J = 1.0;      // sqrt(det C)
  double J_m23 = 1.0;  // J^(-2/3)
  explicit Kinematics(const Eigen::Matrix3d& C_);
};

// Ī = J^(-2/3) C : M with its first and second derivatives with respect to C:
//   dĪ/dC   = J^(-2/3) M - (1/3) Ī C⁻¹
//   d²Ī/dC² = -(1/3)(dĪ ⊗ C⁻¹ + C⁻¹ ⊗ dĪ) - (1/9) Ī C⁻¹ ⊗ C⁻¹ + (1/3) Ī C⁻¹ ⊙ C⁻¹
struct IsochoricInvariant {
  double value = 0.0;
  Eigen::Matrix3d d_dC;
  Voigt6 d2_dC2;
};
IsochoricInvariant isochoric_invariant(const Kinematics& k, const Eigen::Matrix3d& M);

// An isochoric stress S_iso(C) and its tangent D_iso = 2 dS_iso/dC (Pa). It is the part
// the Maxwell branches act on (S∞ of docs/physics.md §2).
class IsochoricPart {
 public:
  virtual ~IsochoricPart() = default;
  virtual void S_iso(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
                     Voigt6& D) const = 0;
  virtual bool isotropic() const { return false; }
};

// Ogden volumetric term Ψ_vol = K β⁻² (β ln J + J^(-β) - 1):
//   S_vol = (K/β)(1 - J^(-β)) C⁻¹,
//   D_vol = K J^(-β) C⁻¹ ⊗ C⁻¹ - 2 (K/β)(1 - J^(-β)) C⁻¹ ⊙ C⁻¹.
// β = 0 is its limit Ψ_vol = K/2 (ln J)², the volumetric law of FEBio's uncoupled
// materials: S_vol = K ln J C⁻¹, D_vol = K C⁻¹ ⊗ C⁻¹ - 2 K ln J C⁻¹ ⊙ C⁻¹.
class OgdenVolumetric {
 public:
  OgdenVolumetric(double K, double beta) : K_(K), beta_(beta) {}
  void S_vol(const Kinematics& k, Eigen::Matrix3d& S, Voigt6& D) const;
  double dPsi_vol_dJ(double J) const;

 private:
  double J_dPsi_dJ(double log_J) const;
  double K_;
  double beta_;  // ≥ 0
};

// Neo-Hookean matrix Ψ_iso = μ/2 (Ī1 - 3): S_iso = μ dĪ1/dC, D_iso = 2 μ d²Ī1/dC².
class NeoHookeanIsochoric : public IsochoricPart {
 public:
  explicit NeoHookeanIsochoric(double mu) : mu_(mu) {}
  void S_iso(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
             Voigt6& D) const override;
  bool isotropic() const override { return true; }

 private:
  double mu_;
};

// Neo-Hookean matrix plus two fiber families Ψ_f = k1/(2 k2)[exp(k2 (I4 - 1)²) - 1] on the
// full invariant I4 = C : A, carrying load only in tension (I4 > 1): S_f = 2 ψ' A,
// D_f = 4 ψ'' A ⊗ A. Not the isochoric Ī4: its projection −(Ī4/3) C⁻¹ loads the thickness
// direction with a compression as large as the fiber stress, which the Ogden volumetric
// term (bounded by K/β in dilation) cannot balance once the fibers stiffen, so plane
// stress had no root (docs/physics.md §2.4).
class FiberFamilies : public IsochoricPart {
 public:
  FiberFamilies(double mu, double k1, double k2) : matrix_(mu), k1_(k1), k2_(k2) {}
  void S_iso(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
             Voigt6& D) const override;

 private:
  NeoHookeanIsochoric matrix_;
  double k1_;
  double k2_;
};

}  // namespace vesica::simulate
