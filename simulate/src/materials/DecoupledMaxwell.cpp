// Generalized Maxwell viscoelasticity of the membrane wall (docs/physics.md §2.5):
//   ξ_α = exp(-Δt / (2 τ_α)),  Q_α,n+1 = ξ_α² Q_α,n + β_α ξ_α (S∞_n+1 - S∞_n),
//   S = S∞ + Σ Q_α,   𝔻 = (1 + Σ β_α ξ_α) 𝔻∞ (+ the muscle's),
// with S∞ the in-plane components S_αβ of the passive elastic stress (volumetric, matrix
// and fibers) at plane stress, S33 = 0: the membrane stress the wall would carry without
// viscosity. evaluate() is the elastic 3-D law with the muscle; the branches are added by
// the plane-stress solve (add_membrane_overstress), because only there is C33 the wall's
// thickness. Why not on the 3-D isochoric stress S_iso: its thickness component grows as
// λ⁶ while the wall thins, and once the wall thickens again its stored history turned into
// a compressive in-plane overstress of several kPa (a voiding bladder that sucked). The
// muscle's active stress (DetrusorMuscle.h) is not viscous; its history follows the
// branches'.
#include <cmath>
#include <memory>
#include <vector>

#include "materials/DecoupledMaxwell.h"

namespace vesica::simulate {
namespace {
constexpr int kPlane[3] = {0, 1, 3};  // Voigt positions of 11, 22, 12
}  // namespace

DecoupledMaxwell::DecoupledMaxwell(OgdenVolumetric volumetric,
                                   std::unique_ptr<IsochoricPart> isochoric,
                                   std::vector<MaxwellBranch> branches,
                                   std::optional<DetrusorMuscle> muscle)
    : volumetric_(volumetric),
      isochoric_(std::move(isochoric)),
      branches_(std::move(branches)),
      muscle_(muscle) {
  // S∞ of the last committed state, then Q of each branch (in-plane Voigt 11, 22, 12).
  muscle_offset_ = branches_.empty() ? 0 : 3 * (1 + branches_.size());
}

std::size_t DecoupledMaxwell::history_size() const {
  return muscle_offset_ + (muscle_ ? DetrusorMuscle::kHistorySize : 0);
}

void DecoupledMaxwell::passive(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
                               Voigt6& D) const {
  Eigen::Matrix3d S_vol;
  Voigt6 D_vol;
  isochoric_->S_iso(k, point, S, D);
  volumetric_.S_vol(k, S_vol, D_vol);
  S += S_vol;
  D += D_vol;
}

void DecoupledMaxwell::evaluate(const Eigen::Matrix3d& C, const MaterialPoint& point,
                                const double* history_old, double* history_new, Eigen::Matrix3d& S,
                                Voigt6& D) const {
  passive(Kinematics(C), point, S, D);
  if (muscle_)
    muscle_->add_stress(C, point, history_old + muscle_offset_, history_new + muscle_offset_, S, D);
}

// The overstress depends on C only through S∞ = S_αβ, so its derivative is Σ β_α ξ_α times
// the in-plane rows of the passive tangent (all six columns, C33 included). Condensed at
// S33 = 0 (PlaneStress.h) these rows give Σ β_α ξ_α 𝔻∞_mem, the derivative of the membrane
// stress along the thickness constraint: symmetric, because S33 is passive too (the muscle
// pulls in the plane only), so the row and the column of C33 are the passive law's.
void DecoupledMaxwell::add_membrane_overstress(const Eigen::Matrix3d& C, const MaterialPoint& point,
                                               const double* history_old, double* history_new,
                                               Eigen::Matrix3d& S, Voigt6& D) const {
  if (branches_.empty()) return;
  Eigen::Matrix3d S_pas;
  Voigt6 D_pas;
  passive(Kinematics(C), point, S_pas, D_pas);
  const Eigen::Vector3d S_inf(S_pas(0, 0), S_pas(1, 1), S_pas(0, 1));
  const Eigen::Map<const Eigen::Vector3d> S_inf_old(history_old);
  Eigen::Map<Eigen::Vector3d> S_inf_new(history_new);
  S_inf_new = S_inf;
  double factor = 0.0;
  Eigen::Vector3d Q_sum = Eigen::Vector3d::Zero();
  for (std::size_t a = 0; a < branches_.size(); ++a) {
    const double xi = std::exp(-point.dt_s / (2.0 * branches_[a].tau_s));
    const Eigen::Map<const Eigen::Vector3d> Q_old(history_old + 3 * (a + 1));
    Eigen::Map<Eigen::Vector3d> Q_new(history_new + 3 * (a + 1));
    Q_new = xi * xi * Q_old + branches_[a].beta * xi * (S_inf - S_inf_old);
    Q_sum += Q_new;
    factor += branches_[a].beta * xi;
  }
  S(0, 0) += Q_sum(0);
  S(1, 1) += Q_sum(1);
  S(0, 1) += Q_sum(2);
  S(1, 0) += Q_sum(2);
  for (int i : kPlane) D.row(i) += factor * D_pas.row(i);
}

}  // namespace vesica::simulate
