#pragma once
// The state of one level-1 run (wall + enclosed urine) and its time step with cut-back:
// each step solves the bordered Newton system under volume control, with the outlet law
// integrated by the trapezoidal rule so that V(t) = V0 + ∫(Q_in - Q_out) dt holds to the
// solver tolerance at every step (mass balance).
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "BossakNewmark.h"
#include "MembraneProblem.h"
#include "NewtonSolver.h"
#include "UrethraLaw.h"
#include "vesica/simulate/Cystometry.h"

namespace vesica::simulate {

class CavityRun {
 public:
  struct StepFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  CavityRun(const WallModel& wall, const Material& material, const CystometryProtocol& protocol,
            const RunOptions& options);

  // Moves to enclosed volume V (m³) without time passing (reference → start volume).
  void step_to_volume(double V);
  // Time and volume bookkeeping start here.
  void start_clock();
  void begin_voiding();
  // Advances by at most dt (s) with inflow q_in (m³/s), the outlet open or closed; halves
  // the step on failure (up to 12 times), then throws StepFailed. Returns the Newton
  // iterations of the accepted step.
  int step(double dt, double q_in, bool outlet);

  double time() const { return t_; }
  double volume() const { return volume_; }
  double infused() const { return infused_; }
  double voided() const { return voided_; }
  double initial_volume() const { return V0_; }
  double initial_reference_volume() const { return V_reference_; }
  double pves() const { return loads_.inside.p0; }
  double pabd() const { return loads_.outside.p0; }
  double outflow() const { return q_out_; }
  const WallModel& wall() const { return wall_; }
  const std::vector<Eigen::Vector3d>& positions() const { return x_; }
  std::vector<MembraneStressOutput> stresses() const;
  nlohmann::json statistics() const;
  // Total force of the fixed dofs on the wall (N), e.g. the support of the urine's weight.
  Eigen::Vector3d support_reaction() const;

 private:
  bool attempt(double dt, double q_in, bool outlet, double V_target_no_flow, int& iterations);
  void predict(double dt);
  void set_time_loads(double t);

  const WallModel& wall_;
  const CystometryProtocol& protocol_;
  UrethraLaw urethra_;
  MembraneProblem problem_;
  NewtonSolver solver_;
  WallLoads loads_;
  std::vector<Eigen::Vector3d> x_;
  // The state before the last timed step and its length: the predictor of the next one.
  std::vector<Eigen::Vector3d> x_before_;
  double p_before_ = 0.0, dt_before_ = 0.0;
  bool smooth_ = false;  // the last step converged quickly, without cut-back
  double t_ = 0.0, t_void_ = -1.0;
  double volume_ = 0.0, V0_ = 0.0, V_reference_ = 0.0;
  double infused_ = 0.0, voided_ = 0.0, q_out_ = 0.0;
  double reference_rate_m3_s_ = 1e-6;        // infusion rate: pseudo-time of volume steps
  std::unique_ptr<BossakNewmark> dynamics_;  // wall inertia; null = quasi-static
  std::string last_failure_;
  int steps_ = 0, iterations_ = 0, cutbacks_ = 0, max_iterations_ = 0;
};

}  // namespace vesica::simulate
