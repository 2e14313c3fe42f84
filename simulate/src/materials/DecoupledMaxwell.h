#pragma once
// The one Material class of the decoupled family: Ogden volumetric + an isochoric part +
// 0..5 Maxwell branches + the detrusor muscle's active fiber stress. See DecoupledMaxwell.cpp.
#include <memory>
#include <optional>
#include <vector>

#include "materials/DecoupledParts.h"
#include "materials/DetrusorMuscle.h"

namespace vesica::simulate {

struct MaxwellBranch {
  double beta = 0.0;   // β_α, dimensionless
  double tau_s = 1.0;  // τ_α (s)
};

class DecoupledMaxwell : public Material {
 public:
  // muscle: the active stress, none for a passive wall.
  DecoupledMaxwell(OgdenVolumetric volumetric, std::unique_ptr<IsochoricPart> isochoric,
                   std::vector<MaxwellBranch> branches,
                   std::optional<DetrusorMuscle> muscle = std::nullopt);
  std::size_t history_size() const override;
  bool isotropic_elastic() const override {
    return branches_.empty() && isochoric_->isotropic() && !muscle_;
  }
  void evaluate(const Eigen::Matrix3d& C, const MaterialPoint& point, const double* history_old,
                double* history_new, Eigen::Matrix3d& S, Voigt6& D) const override;
  void add_membrane_overstress(const Eigen::Matrix3d& C, const MaterialPoint& point,
                               const double* history_old, double* history_new, Eigen::Matrix3d& S,
                               Voigt6& D) const override;

 private:
  OgdenVolumetric volumetric_;
  std::unique_ptr<IsochoricPart> isochoric_;
  std::vector<MaxwellBranch> branches_;
  std::optional<DetrusorMuscle> muscle_;
  void passive(const Kinematics& k, const MaterialPoint& point, Eigen::Matrix3d& S,
               Voigt6& D) const;
  std::size_t muscle_offset_ = 0;  // where the muscle's history starts
};

}  // namespace vesica::simulate
