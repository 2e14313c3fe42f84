#pragma once
// Level 1 of the cavity models (CavityModel.h; docs/physics.md §4): the urine is an
// enclosed incompressible volume with a hydrostatic pressure field, p = p0 + ρ g·(x − x_ref),
// whose pressure p0 at the reference point is solved together with the wall (bordered
// Newton under volume control, NewtonSolver.h). A timed step's volume is the protocol's
// bookkeeping plus the infusion minus the outflow through the urethra law, integrated by the
// trapezoidal rule (implicit in p0), so that V(t) = V0 + ∫(Q_in − Q_out) dt holds to the
// solver tolerance at every step (mass balance). Steps are quasi-static, or with the wall's
// inertia (Bossak–Newmark, RunOptions::dynamic).
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cavity/CavityModel.h"
#include "solver/BossakNewmark.h"
#include "solver/NewtonSolver.h"
#include "solver/StepStatistics.h"
#include "vesica/simulate/protocol/CystometrySettings.h"
#include "wall/MembraneProblem.h"

namespace vesica::simulate {

class HydrostaticCavity final : public CavityModel {
 public:
  // Keeps references to wall, material and settings.
  HydrostaticCavity(const WallModel& wall, const Material& material,
                    const ProtocolSettings& settings, const RunOptions& options);

  StepResult try_volume_step(double volume_m3, const ProtocolLoads& loads) override;
  void start_clock() override;
  void urethra_opens(const UrethraLaw& urethra) override;
  StepResult try_step(const StepRequest& step) override;
  // Continues, with the clock running, from a more detailed model's state on the same wall
  // (level 2's, LevelLadder.h): the wall at its positions with its committed history, the
  // pressure, outflow, bookkeeping and loads. Throws std::runtime_error when the state has
  // no membrane wall to carry on.
  void continue_from(const CarriedState& state);
  int level() const override { return 1; }
  CarriedState carried_state() const override;
  // Below the stress-free volume a failed voiding step ends voiding: the wall is slack
  // there and its tension field may have no solution (docs/simulate.md).
  std::string voiding_end_note(const std::string& failure) const override;

  double volume() const override { return volume_; }
  double pves() const override { return loads_.inside.p0; }
  double outflow() const override { return q_out_; }
  double reference_volume() const override { return V_reference_; }
  const WallModel& wall() const override { return wall_; }
  std::vector<Eigen::Vector3d> wall_positions() const override { return x_; }
  std::vector<MembraneStressOutput> wall_stresses() const override;
  nlohmann::json statistics() const override { return statistics_.json(); }

  // Checkpoints (HydrostaticCavityState.cpp): the wall, its history and dynamics, the
  // pressure and bookkeeping, and what the solver carries to the next step.
  bool saves_state() const override { return true; }
  void save_state(CheckpointWriter& out) const override;
  void restore_state(CheckpointReader& in) override;

 private:
  // One Newton solve to the step's end; restores the state when it does not converge.
  bool attempt(double dt, const ProtocolLoads& loads, const UrethraLaw* urethra,
               double V_target_no_flow, int& iterations, double& voided);
  void predict(double dt, bool contracting);
  void log_step(double dt, const ProtocolLoads& loads, const NewtonReport& report) const;
  void set_loads(const ProtocolLoads& loads);
  StepResult accepted(int iterations, double voided);
  StepResult failed(int iterations);

  const WallModel& wall_;
  const Material& material_;
  const ProtocolSettings& settings_;
  MembraneProblem problem_;
  NewtonSolver solver_;
  WallLoads loads_;
  ProtocolLoads committed_loads_;  // of the last converged state
  std::vector<Eigen::Vector3d> x_;
  // The state before the last timed step and its length: the predictor of the next one.
  std::vector<Eigen::Vector3d> x_before_;
  double p_before_ = 0.0, dt_before_ = 0.0;
  bool smooth_ = false;  // the last step converged quickly, without cut-back
  double volume_ = 0.0, V0_ = 0.0, V_reference_ = 0.0, q_out_ = 0.0;
  double reference_rate_m3_s_ = 1e-6;        // infusion rate: pseudo-time of volume steps
  std::unique_ptr<BossakNewmark> dynamics_;  // wall inertia; null = quasi-static
  std::string last_failure_;
  // Iterations of converged attempts; a converged step's cut-backs are the failed attempts
  // before it.
  StepStatistics statistics_;
  int failed_attempts_ = 0;  // since the last converged step
};

}  // namespace vesica::simulate
