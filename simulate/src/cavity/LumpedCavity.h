#pragma once
// Level 0 of the cavity models (CavityModel.h; docs/physics.md §11): the bladder as one
// thin sphere, the sphere-equivalent of the wall — its stress-free volume V_ref and its
// area-weighted mean thickness H. The wall's material is evaluated at the sphere's
// equibiaxial stretch λ = (V/V_ref)^(1/3) with plane stress (and the tension field), the
// very Material object, activation, Hill relation and urethra law of levels 1 and 2, and
// Laplace's law gives the transmural pressure
//   Pdet = 2 S₁₁ H / (R λ),   R = (3 V_ref / 4π)^(1/3)
// (S₁₁ H is the membrane tension per unit current length). Volume control with the same
// trapezoidal outflow as level 1: a voiding step solves one scalar equation for V. A whole
// cystometry costs milliseconds: the fast global search of calibration.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cavity/CavityModel.h"
#include "solver/StepStatistics.h"
#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/protocol/CystometrySettings.h"
#include "wall/PlaneStress.h"

namespace vesica::simulate {

class LumpedCavity final : public CavityModel {
 public:
  // Keeps references to wall, material and settings.
  LumpedCavity(const WallModel& wall, const Material& material, const ProtocolSettings& settings);

  StepResult try_volume_step(double volume_m3, const ProtocolLoads& loads) override;
  void start_clock() override { V0_ = volume_; }
  void urethra_opens(const UrethraLaw& urethra) override { q_out_ = urethra.flow(pves()); }
  StepResult try_step(const StepRequest& step) override;

  double volume() const override { return volume_; }
  double pves() const override { return pabd_ + pdet_; }
  double outflow() const override { return q_out_; }
  double reference_volume() const override { return V_reference_; }
  const WallModel& wall() const override { return wall_; }
  // The wall's nodes scaled about their centroid by λ: the sphere's motion drawn on the
  // patient's wall (frames only; the sphere carries the mechanics).
  std::vector<Eigen::Vector3d> wall_positions() const override;
  std::vector<MembraneStressOutput> wall_stresses() const override;
  nlohmann::json statistics() const override { return statistics_.json(); }
  void add_summary(nlohmann::json& summary) const override;

  int level() const override { return 0; }
  // Below the stress-free volume a failed voiding step ends voiding, as at level 1.
  std::string voiding_end_note(const std::string& failure) const override;
  std::vector<std::string> take_notes() override;

  // Continues the voiding of a wall (level 1) that could not go on (LevelLadder.h), from
  // its state: the sphere's history is the relaxed one at the volume before the wall's
  // last step, then that step (the fibers' shortening rate of the wall's last step for the
  // Hill relation), and its pressure is scaled from then on by the wall's Pdet over its own
  // (the shape factor of a wall that is not a sphere, clamped to [1/4, 4]; 1 where either
  // is not positive): pressure_scale(). Its frames are then the wall as handed over,
  // scaled to the volume. Throws std::runtime_error without a last step to start from.
  void take_over(const CarriedState& wall);
  double pressure_scale() const { return pressure_scale_; }  // take_over's; 1 before it

  // The sphere-equivalent's reference radius (m) and thickness (m).
  double radius() const { return R_; }
  double thickness() const { return H_; }

 private:
  // The wall at volume V after a step of dt from the committed state: its transmural
  // pressure (Pa); fills trial_ (stress, history). Throws std::runtime_error when plane
  // stress fails.
  double wall_pressure(double V, double dt, double activation);
  // Solves V + θ dt Q(Pabd + Pdet(V)) = V_base for the end of a voiding step.
  double voided_volume(double V_base, const StepRequest& step);
  StepResult accept(double V);
  StepResult failed(const std::string& why);

  const WallModel& wall_;
  const Material& material_;
  const ProtocolSettings& settings_;
  double R_ = 0.0, H_ = 0.0, V_reference_ = 0.0;
  double volume_ = 0.0, V0_ = 0.0, pdet_ = 0.0, pabd_ = 0.0, q_out_ = 0.0;
  double pressure_scale_ = 1.0;  // take_over's shape factor
  // What the frames draw, scaled about centre_drawn_ by (V/V_drawn_)^(1/3): the reference
  // wall about its area centroid, or after take_over the wall as handed over, about its
  // mean node.
  std::vector<Eigen::Vector3d> x_drawn_;
  Eigen::Vector3d centre_drawn_ = Eigen::Vector3d::Zero();
  double V_drawn_ = 0.0;
  bool taken_over_ = false;
  std::vector<std::string> notes_;
  // The point's history: committed, and of the last trial evaluation.
  std::vector<double> history_, trial_history_;
  PlaneStressState state_, trial_;
  StepStatistics statistics_;
  int evaluations_ = 0;  // material evaluations of the step being tried
};

}  // namespace vesica::simulate
