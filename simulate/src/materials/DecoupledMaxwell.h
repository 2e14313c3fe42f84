#pragma once
// The one Material class of the decoupled family: Ogden volumetric + an isochoric part +
// 0..5 Maxwell branches + the active fiber stress. See DecoupledMaxwell.cpp.
#include <memory>
#include <vector>

#include "materials/DecoupledParts.h"

namespace vesica::simulate {

struct MaxwellBranch {
  double beta = 0.0;   // β_α, dimensionless
  double tau_s = 1.0;  // τ_α (s)
};

class DecoupledMaxwell : public Material {
 public:
  DecoupledMaxwell(OgdenVolumetric volumetric, std::unique_ptr<IsochoricPart> isochoric,
                   std::vector<MaxwellBranch> branches);
  std::size_t history_size() const override;
  bool isotropic_elastic() const override { return branches_.empty() && isochoric_->isotropic(); }
  void evaluate(const Eigen::Matrix3d& C, const MaterialPoint& point, const double* history_old,
                double* history_new, Eigen::Matrix3d& S, Voigt6& D) const override;

 private:
  OgdenVolumetric volumetric_;
  std::unique_ptr<IsochoricPart> isochoric_;
  std::vector<MaxwellBranch> branches_;
};

}  // namespace vesica::simulate
