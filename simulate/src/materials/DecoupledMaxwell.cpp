// Generalized Maxwell viscoelasticity on the isochoric stress (docs/physics.md §2):
//   ξ_α = exp(-Δt / (2 τ_α)),  Q_α,n+1 = ξ_α² Q_α,n + β_α ξ_α (S∞_n+1 - S∞_n),
//   S = S_vol + S∞ + Σ Q_α,   D = D_vol + (1 + Σ β_α ξ_α) D∞,
// with S∞ = S_iso (matrix, and fibers when present). With no branch it is the elastic
// decoupled material. The muscle's active stress (DetrusorMuscle.h) is added on top and is
// not viscous; its own history follows the branches'.
#include <cmath>
#include <memory>
#include <vector>

#include "DecoupledMaxwell.h"

namespace vesica::simulate {

DecoupledMaxwell::DecoupledMaxwell(OgdenVolumetric volumetric,
                                   std::unique_ptr<IsochoricPart> isochoric,
                                   std::vector<MaxwellBranch> branches,
                                   std::optional<DetrusorMuscle> muscle)
    : volumetric_(volumetric),
      isochoric_(std::move(isochoric)),
      branches_(std::move(branches)),
      muscle_(std::move(muscle)) {
  // S∞ of the last committed state, then Q of each branch (6 Voigt components each).
  muscle_offset_ = branches_.empty() ? 0 : 6 * (1 + branches_.size());
}

std::size_t DecoupledMaxwell::history_size() const {
  return muscle_offset_ + (muscle_ ? DetrusorMuscle::kHistorySize : 0);
}

void DecoupledMaxwell::evaluate(const Eigen::Matrix3d& C, const MaterialPoint& point,
                                const double* history_old, double* history_new, Eigen::Matrix3d& S,
                                Voigt6& D) const {
  const Kinematics k(C);
  Eigen::Matrix3d S_inf, S_vol;
  Voigt6 D_inf, D_vol;
  isochoric_->S_iso(k, point, S_inf, D_inf);
  volumetric_.S_vol(k, S_vol, D_vol);
  S = S_vol + S_inf;
  D = D_vol + D_inf;
  if (!branches_.empty()) {
    const Vector6 S_inf_v = to_voigt(S_inf);
    const Eigen::Map<const Vector6> S_inf_old(history_old);
    Eigen::Map<Vector6> S_inf_new(history_new);
    S_inf_new = S_inf_v;
    double factor = 0.0;
    for (std::size_t a = 0; a < branches_.size(); ++a) {
      const double xi = std::exp(-point.dt_s / (2.0 * branches_[a].tau_s));
      const Eigen::Map<const Vector6> Q_old(history_old + 6 * (a + 1));
      Eigen::Map<Vector6> Q_new(history_new + 6 * (a + 1));
      Q_new = xi * xi * Q_old + branches_[a].beta * xi * (S_inf_v - S_inf_old);
      S += from_voigt(Q_new);
      factor += branches_[a].beta * xi;
    }
    D += factor * D_inf;
  }
  if (muscle_)
    muscle_->add_stress(C, point, history_old + muscle_offset_, history_new + muscle_offset_, S, D);
}

}  // namespace vesica::simulate
