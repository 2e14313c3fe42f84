#include "CavityRun.h"

#include <algorithm>
#include <cmath>

#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {

// A step that converges within this many iterations is on a smooth path (predict()).
constexpr int kSmoothIterations = 5;

double ramp(double t, double duration) {
  if (t <= 0.0) return 0.0;
  return duration > 0.0 ? std::min(1.0, t / duration) : 1.0;
}

}  // namespace

CavityRun::CavityRun(const WallModel& wall, const Material& material,
                     const CystometryProtocol& protocol, const RunOptions& options)
    : wall_(wall),
      protocol_(protocol),
      urethra_(UrethraLaw::from_clinical_units(protocol.p_open_cmh2o, protocol.r1_cmh2o_s_per_ml,
                                               protocol.r2_cmh2o_s2_per_ml2)),
      problem_(wall, material, options.threads),
      solver_(problem_, options.newton),
      x_(wall.nodes) {
  problem_.set_tension_field(protocol.wrinkling);
  const Eigen::Vector3d g =
      protocol.gravity ? gravity_lps(protocol.posture) : Eigen::Vector3d::Zero();
  loads_.inside.rho = protocol.urine_density;
  loads_.inside.gravity = g;
  loads_.inside.x_ref = pressure_reference_point(wall, g);
  // The abdomen is a fluid too: its hydrostatic gradient acts on the outer face.
  loads_.outside.rho = protocol.abdominal_density;
  loads_.outside.gravity = g;
  loads_.outside.x_ref = loads_.inside.x_ref;
  if (protocol.wall_weight) loads_.wall_gravity = g;
  loads_.wall_density = protocol.wall_density;
  loads_.support_stiffness = protocol.support_kpa_per_mm * 1e3 / 1e-3;  // kPa/mm → Pa/m
  set_time_loads(0.0);
  if (options.dynamic)
    dynamics_ = std::make_unique<BossakNewmark>(wall.node_count(), options.bossak_alpha);
  volume_ = V_reference_ = enclosed_volume(wall, x_);
  reference_rate_m3_s_ = units::m3s_from_ml_per_min(protocol.fill_rate_ml_min);
}

void CavityRun::set_time_loads(double t) {
  const double active = t_void_ >= 0.0 ? ramp(t - t_void_, protocol_.activation_ramp_s) : 0.0;
  loads_.outside.p0 = units::pa_from_cmh2o(protocol_.pabd_cmh2o) +
                      active * units::pa_from_kpa(protocol_.straining_kpa);
  loads_.active_stress_pa = active * units::pa_from_kpa(protocol_.detrusor_kpa);
}

bool CavityRun::attempt(double dt, double q_in, bool outlet, double V_target_no_flow,
                        int& iterations) {
  const std::vector<Eigen::Vector3d> x_saved = x_;
  const double p_saved = loads_.inside.p0;
  set_time_loads(t_ + dt);
  loads_.dt_s = dt;
  // Drag towards the last converged wall; a volume step without time (reference to
  // start volume) takes the time the infusion rate would need for it.
  const double drag_dt =
      dt > 0.0 ? dt : std::abs(V_target_no_flow - volume_) / reference_rate_m3_s_;
  loads_.drag_stiffness = drag_dt > 0.0 ? protocol_.wall_drag_pa_s_per_m / drag_dt : 0.0;
  loads_.drag_anchor = x_saved;
  if (dynamics_) loads_.inertia = dynamics_->inertia(x_saved, dt);
  predict(dt);
  CavityEquation cavity;
  cavity.volume_control = true;
  constexpr double theta = 0.5;  // trapezoidal outflow: second order, exact bookkeeping
  cavity.volume_base_m3 = V_target_no_flow - (outlet ? (1.0 - theta) * dt * q_out_ : 0.0);
  if (outlet)
    cavity.outflow = [this, dt](double p0, double& d) {
      d = urethra_.flow_derivative(p0) * (theta * dt);
      return theta * dt * urethra_.flow(p0);
    };
  (void)q_in;
  const NewtonReport report = solver_.solve(cavity, loads_, x_);
  iterations = report.iterations;
  if (!report.converged) {
    x_ = x_saved;
    loads_.inside.p0 = p_saved;
    set_time_loads(t_);
    last_failure_ = report.failure;
    return false;
  }
  problem_.commit();
  if (dynamics_) dynamics_->commit(x_saved, x_, dt);
  x_before_ = x_saved;
  p_before_ = p_saved;
  dt_before_ = dt;
  const double q_new = outlet ? urethra_.flow(loads_.inside.p0) : 0.0;
  if (outlet) voided_ += dt * (theta * q_new + (1.0 - theta) * q_out_);
  q_out_ = q_new;
  volume_ = solver_.assembly().volume;
  return true;
}

// Newton starts from the last state moved on at the last step's velocity (wall and
// pressure): the tissue drag resists the wall's velocity, so from the last state
// (velocity zero) the first residual is the whole drag force of the last step; from the
// extrapolated one only its change is left, and a taut wall's step converges in 2
// iterations instead of 3. Only on a smooth path: where the last step was hard (a slack
// wall wrinkling) its velocity says little about the next one, and extrapolating it
// starts Newton further away. At most twice the last step, like the step growth.
void CavityRun::predict(double dt) {
  if (!(dt > 0.0 && dt_before_ > 0.0 && smooth_) || x_before_.size() != x_.size()) return;
  const double r = std::min(dt / dt_before_, 2.0);
  for (std::size_t n = 0; n < x_.size(); ++n) x_[n] += r * (x_[n] - x_before_[n]);
  loads_.inside.p0 += r * (loads_.inside.p0 - p_before_);
}

void CavityRun::step_to_volume(double V) {
  int its = 0;
  for (int cut = 0; cut <= 12; ++cut) {
    const double target = volume_ + (V - volume_) / std::pow(2.0, cut);
    if (attempt(0.0, 0.0, false, target, its)) {
      ++steps_;
      iterations_ += its;
      max_iterations_ = std::max(max_iterations_, its);
      if (cut > 0) {
        cutbacks_ += cut;
        step_to_volume(V);
      }
      return;
    }
  }
  throw StepFailed("no equilibrium at " + std::to_string(units::ml_from_m3(V)) + " ml (" +
                   last_failure_ + ")");
}

void CavityRun::start_clock() {
  t_ = 0.0;
  V0_ = volume_;
  infused_ = voided_ = 0.0;
}

void CavityRun::begin_voiding() {
  t_void_ = t_;
  q_out_ = urethra_.flow(loads_.inside.p0);  // the outlet opens on the current pressure
}

int CavityRun::step(double dt, double q_in, bool outlet) {
  for (int cut = 0; cut <= 12; ++cut, dt *= 0.5) {
    int its = 0;
    const double V_target = V0_ + infused_ + dt * q_in - voided_;
    if (attempt(dt, q_in, outlet, V_target, its)) {
      smooth_ = cut == 0 && its <= kSmoothIterations;
      t_ += dt;
      infused_ += dt * q_in;
      ++steps_;
      iterations_ += its;
      cutbacks_ += cut;
      max_iterations_ = std::max(max_iterations_, its);
      return its;
    }
    smooth_ = false;  // retry the shorter step from the last state
  }
  throw StepFailed(last_failure_ + " after 12 step cut-backs");
}

std::vector<MembraneStressOutput> CavityRun::stresses() const {
  return problem_.element_outputs(x_, loads_);
}

nlohmann::json CavityRun::statistics() const {
  return {{"steps", steps_},
          {"iterations", iterations_},
          {"cutbacks", cutbacks_},
          {"max_iterations_per_step", max_iterations_},
          {"mean_iterations_per_step", steps_ ? double(iterations_) / steps_ : 0.0}};
}

Eigen::Vector3d CavityRun::support_reaction() const {
  Eigen::Vector3d R = Eigen::Vector3d::Zero();
  const Eigen::VectorXd& r = solver_.assembly().full_residual;
  for (std::size_t n = 0; n < wall_.node_count(); ++n)
    for (int i = 0; i < 3; ++i)
      if (problem_.dof_map()[3 * n + i] < 0) R(i) += r(3 * n + i);
  return R;
}

}  // namespace vesica::simulate
