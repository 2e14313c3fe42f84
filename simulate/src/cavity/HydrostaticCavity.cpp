#include "cavity/HydrostaticCavity.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "vesica/core/Log.h"
#include "vesica/core/Units.h"
#include "wall/WallSurroundings.h"

namespace vesica::simulate {
namespace {

// A step that converges within this many iterations is on a smooth path (predict()).
constexpr int kSmoothIterations = 5;
// The outflow over a step is θ Q(t_n+1) + (1 − θ) Q(t_n): the trapezoidal rule, second
// order, with exact bookkeeping.
constexpr double kTheta = 0.5;

}  // namespace

HydrostaticCavity::HydrostaticCavity(const WallModel& wall, const Material& material,
                                     const ProtocolSettings& settings, const RunOptions& options)
    : wall_(wall),
      material_(material),
      settings_(settings),
      problem_(wall, material, options.threads),
      solver_(problem_, options.newton),
      x_(wall.nodes) {
  problem_.set_tension_field(settings.wrinkling);
  problem_.set_wrinkle_regularisation(settings.wrinkle_regularisation);
  const Eigen::Vector3d g = protocol_gravity(settings);
  const Eigen::Vector3d x_ref = pressure_reference_point(wall, g);
  loads_ = surroundings(settings, g, x_ref);
  loads_.inside.rho = settings.urine_density;
  loads_.inside.gravity = g;
  loads_.inside.x_ref = x_ref;
  committed_loads_.pabd_pa = units::pa_from_cmh2o(settings.pabd_cmh2o);
  set_loads(committed_loads_);
  if (options.dynamic)
    dynamics_ = std::make_unique<BossakNewmark>(wall.node_count(), options.bossak_alpha);
  volume_ = V_reference_ = enclosed_volume(wall, x_);
  reference_rate_m3_s_ = units::m3s_from_ml_per_min(settings.fill_rate_ml_min);
  if (!options.checkpoints.file.empty()) solver_.keep_factorized_matrix();
}

void HydrostaticCavity::set_loads(const ProtocolLoads& loads) {
  loads_.outside.p0 = loads.pabd_pa;
  loads_.activation = loads.activation;
}

bool HydrostaticCavity::attempt(double dt, const ProtocolLoads& loads, const UrethraLaw* urethra,
                                double V_target_no_flow, int& iterations, double& voided) {
  const std::vector<Eigen::Vector3d> x_saved = x_;
  const double p_saved = loads_.inside.p0;
  set_loads(loads);
  // A volume step without time (settling to the start volume) is a state held for long,
  // as before a cystometry: the wall's relaxed response, not its instantaneous one.
  loads_.dt_s = dt > 0.0 ? dt : kRelaxedStep;
  // Drag towards the last converged wall; a volume step without time (reference to
  // start volume) takes the time the infusion rate would need for it.
  const double drag_dt =
      dt > 0.0 ? dt : std::abs(V_target_no_flow - volume_) / reference_rate_m3_s_;
  loads_.drag_stiffness = drag_dt > 0.0 ? settings_.wall_drag_pa_s_per_m / drag_dt : 0.0;
  loads_.drag_anchor = x_saved;
  if (dynamics_) loads_.inertia = dynamics_->inertia(x_saved, dt);
  predict(dt, loads.activation > 0.0);
  CavityEquation cavity;
  cavity.volume_control = true;
  cavity.volume_base_m3 = V_target_no_flow - (urethra ? (1.0 - kTheta) * dt * q_out_ : 0.0);
  if (urethra)
    cavity.outflow = [urethra, dt](double p0, double& d) {
      d = urethra->flow_derivative(p0) * (kTheta * dt);
      return kTheta * dt * urethra->flow(p0);
    };
  const NewtonReport report = solver_.solve(cavity, loads_, x_);
  iterations = report.iterations;
  log_step(dt, loads, report);
  if (!report.converged) {
    x_ = x_saved;
    loads_.inside.p0 = p_saved;
    set_loads(committed_loads_);
    last_failure_ = report.failure;
    return false;
  }
  problem_.commit();
  if (dynamics_) dynamics_->commit(x_saved, x_, dt);
  x_before_ = x_saved;
  p_before_ = p_saved;
  dt_before_ = dt;
  committed_loads_ = loads;
  const double q_new = urethra ? urethra->flow(loads_.inside.p0) : 0.0;
  voided = urethra ? dt * (kTheta * q_new + (1.0 - kTheta) * q_out_) : 0.0;
  q_out_ = q_new;
  volume_ = solver_.assembly().volume;
  return true;
}

// One debug line per attempt (docs/simulate.md, "Step log"): where the step went and how
// the wall's elements stood at its last evaluation.
void HydrostaticCavity::log_step(double dt, const ProtocolLoads& loads,
                                 const NewtonReport& report) const {
  const auto log = vesica::log();
  if (!log->should_log(spdlog::level::debug)) return;
  const std::array<int, 3> states = problem_.wrinkling_counts();
  const std::vector<double>& r = report.residual_norms;
  log->debug(
      "level 1 step: dt = {:.4g} s, V = {:.5g} ml, Pves = {:.5g} cmH2O, activation = {:.3f}, "
      "elements taut/wrinkled/slack = {}/{}/{}, {} iterations, |r|/|f| {:.2e} -> {:.2e}: {}",
      dt, units::ml_from_m3(solver_.assembly().volume), units::cmh2o_from_pa(loads_.inside.p0),
      loads.activation, states[0], states[1], states[2], report.iterations,
      r.empty() ? 0.0 : r.front(), r.empty() ? 0.0 : r.back(),
      report.converged ? "converged" : report.failure);
}

// Newton starts from the last state moved on at the last step's velocity (wall and
// pressure): the tissue drag resists the wall's velocity, so from the last state
// (velocity zero) the first residual is the whole drag force of the last step; from the
// extrapolated one only its change is left, and a taut wall's step converges in 2
// iterations instead of 3. On a smooth path, or while the detrusor contracts: where the
// last step was hard (a slack wall wrinkling) its velocity says little about the next one
// and extrapolating it starts Newton further away, except that a contracting wall's Hill
// factor depends on that velocity, and from velocity zero (factor 1) every step, however
// short, starts far from its solution (physics.md §3.7). At most twice the last step,
// like the step growth.
void HydrostaticCavity::predict(double dt, bool contracting) {
  if (!(dt > 0.0 && dt_before_ > 0.0 && (smooth_ || contracting)) || x_before_.size() != x_.size())
    return;
  const double r = std::min(dt / dt_before_, 2.0);
  for (std::size_t n = 0; n < x_.size(); ++n) x_[n] += r * (x_[n] - x_before_[n]);
  loads_.inside.p0 += r * (loads_.inside.p0 - p_before_);
}

StepResult HydrostaticCavity::accepted(int iterations, double voided) {
  statistics_.converged_step(iterations);
  statistics_.iterations += iterations;
  statistics_.cutbacks += failed_attempts_;
  failed_attempts_ = 0;
  StepResult r;
  r.converged = true;
  r.iterations = iterations;
  r.voided_m3 = voided;
  return r;
}

StepResult HydrostaticCavity::failed(int iterations) {
  ++failed_attempts_;
  StepResult r;
  r.iterations = iterations;
  r.failure = last_failure_;
  return r;
}

StepResult HydrostaticCavity::try_volume_step(double volume_m3, const ProtocolLoads& loads) {
  int iterations = 0;
  double voided = 0.0;
  if (attempt(0.0, loads, nullptr, volume_m3, iterations, voided))
    return accepted(iterations, voided);
  return failed(iterations);
}

void HydrostaticCavity::start_clock() {
  V0_ = volume_;
}

std::string HydrostaticCavity::voiding_end_note(const std::string& failure) const {
  if (volume() > reference_volume()) return "";
  return "voiding ended at " + std::to_string(units::ml_from_m3(volume())) +
         " ml, below the stress-free volume, where the slack wall's tension field has no "
         "solution (" +
         failure + ")";
}

void HydrostaticCavity::urethra_opens(const UrethraLaw& urethra) {
  q_out_ = urethra.flow(loads_.inside.p0);  // the urethra opens on the current pressure
}

StepResult HydrostaticCavity::try_step(const StepRequest& step) {
  const double V_target = V0_ + step.infused_m3 + step.dt_s * step.inflow_m3_s - step.voided_m3;
  int iterations = 0;
  double voided = 0.0;
  if (attempt(step.dt_s, step.loads, step.urethra, V_target, iterations, voided)) {
    smooth_ = failed_attempts_ == 0 && iterations <= kSmoothIterations;
    return accepted(iterations, voided);
  }
  smooth_ = false;  // retry the shorter step from the last state
  return failed(iterations);
}

void HydrostaticCavity::continue_from(const CarriedState& state) {
  if (!state.wall_history || state.wall_positions.size() != x_.size())
    throw std::runtime_error("the state carried has no membrane wall of this mesh");
  x_ = state.wall_positions;
  problem_.copy_committed_state(*state.wall_history);
  loads_.inside.p0 = state.pves_pa;
  q_out_ = state.outflow_m3_s;
  V0_ = state.start_volume_m3;
  volume_ = enclosed_volume(wall_, x_);
  committed_loads_ = state.loads;
  set_loads(state.loads);
  x_before_.clear();  // no last step to extrapolate from
  dt_before_ = 0.0;
  smooth_ = false;
}

CarriedState HydrostaticCavity::carried_state() const {
  CarriedState s;
  s.volume_m3 = volume_;
  s.pves_pa = loads_.inside.p0;
  s.outflow_m3_s = q_out_;
  s.start_volume_m3 = V0_;
  s.loads = committed_loads_;
  if (dt_before_ > 0.0 && x_before_.size() == x_.size()) {
    s.volume_before_m3 = enclosed_volume(wall_, x_before_);
    s.dt_before_s = dt_before_;
  }
  s.wall_positions = x_;
  s.wall_history = &problem_;
  return s;
}

std::vector<MembraneStressOutput> HydrostaticCavity::wall_stresses() const {
  return problem_.element_outputs(x_, loads_);
}

}  // namespace vesica::simulate
