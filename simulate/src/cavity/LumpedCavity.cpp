#include "cavity/LumpedCavity.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "vesica/core/Units.h"
#include "wall/TensionField.h"

namespace vesica::simulate {
namespace {

constexpr double kPi = 3.14159265358979323846;
// The outflow over a step is θ Q(t_n+1) + (1 − θ) Q(t_n), as at level 1.
constexpr double kTheta = 0.5;
// The voiding equation is solved to this fraction of the volume.
constexpr double kVolumeTolerance = 1e-12;
constexpr int kMaxEvaluations = 200;

}  // namespace

LumpedCavity::LumpedCavity(const WallModel& wall, const Material& material,
                           const ProtocolSettings& settings)
    : wall_(wall), material_(material), settings_(settings), x_drawn_(wall.nodes) {
  V_reference_ = enclosed_volume(wall, wall.nodes);
  R_ = std::cbrt(3.0 * V_reference_ / (4.0 * kPi));
  // Area-weighted mean thickness and the area centroid (the frames' scaling centre).
  double area = 0.0, thickness_area = 0.0;
  for (std::size_t e = 0; e < wall.triangle_count(); ++e) {
    const auto& t = wall.triangles[e];
    const Eigen::Vector3d& a = wall.nodes[t[0]];
    const double A = 0.5 * (wall.nodes[t[1]] - a).cross(wall.nodes[t[2]] - a).norm();
    area += A;
    thickness_area += A * wall.thickness[e];
    centre_drawn_ += A * (a + wall.nodes[t[1]] + wall.nodes[t[2]]) / 3.0;
  }
  H_ = thickness_area / area;
  centre_drawn_ /= area;
  history_.assign(material.history_size(), 0.0);
  trial_history_ = history_;
  volume_ = V_drawn_ = V_reference_;
  pabd_ = units::pa_from_cmh2o(settings.pabd_cmh2o);
}

double LumpedCavity::wall_pressure(double V, double dt, double activation) {
  if (!(V > 0.0)) throw std::runtime_error("non-positive volume");
  ++evaluations_;
  const double lambda = std::cbrt(V / V_reference_);
  MaterialPoint point;
  point.dt_s = dt;
  point.activation = activation;
  const Eigen::Matrix2d C2 = lambda * lambda * Eigen::Matrix2d::Identity();
  trial_ = settings_.wrinkling ? tension_field_stress(material_, C2, point, state_.J2,
                                                      history_.data(), trial_history_.data())
                               : plane_stress(material_, C2, point, state_.J2, history_.data(),
                                              trial_history_.data());
  return pressure_scale_ * 2.0 * trial_.S(0, 0) * H_ / (R_ * lambda);
}

void LumpedCavity::take_over(const CarriedState& wall) {
  if (!(wall.dt_before_s > 0.0) || !(wall.volume_before_m3 > 0.0))
    throw std::runtime_error("no last step of the wall to carry on from");
  V0_ = wall.start_volume_m3;
  pabd_ = wall.loads.pabd_pa;
  q_out_ = wall.outflow_m3_s;
  pressure_scale_ = 1.0;
  history_.assign(material_.history_size(), 0.0);
  trial_history_ = history_;
  wall_pressure(wall.volume_before_m3, kRelaxedStep, wall.loads.activation);
  accept(wall.volume_before_m3);
  const double own = wall_pressure(wall.volume_m3, wall.dt_before_s, wall.loads.activation);
  accept(wall.volume_m3);
  constexpr double kLargestScale = 4.0;
  const double wall_pdet = wall.pves_pa - wall.loads.pabd_pa;
  if (own > 0.0 && wall_pdet > 0.0)
    pressure_scale_ = std::clamp(wall_pdet / own, 1.0 / kLargestScale, kLargestScale);
  pdet_ = pressure_scale_ * own;
  // From here the frames draw the wall as handed over, about its mean node.
  x_drawn_ = wall.wall_positions;
  V_drawn_ = wall.volume_m3;
  centre_drawn_ = Eigen::Vector3d::Zero();
  for (const auto& p : x_drawn_) centre_drawn_ += p;
  centre_drawn_ /= static_cast<double>(x_drawn_.size());
  taken_over_ = true;
  std::ostringstream note;
  note.precision(4);
  note << "the sphere-equivalent (level 0) carries on with its pressure scaled by "
       << pressure_scale_ << " to the wall's";
  notes_.push_back(note.str());
}

std::string LumpedCavity::voiding_end_note(const std::string& failure) const {
  if (volume_ > V_reference_) return "";
  return "voiding ended at " + std::to_string(units::ml_from_m3(volume_)) +
         " ml, below the stress-free volume, where the sphere-equivalent could not go on (" +
         failure + ")";
}

std::vector<std::string> LumpedCavity::take_notes() {
  return std::exchange(notes_, {});
}

StepResult LumpedCavity::accept(double V) {
  volume_ = V;
  history_ = trial_history_;
  state_ = trial_;
  statistics_.converged_step(evaluations_);
  statistics_.iterations += evaluations_;
  StepResult r;
  r.converged = true;
  r.iterations = evaluations_;
  evaluations_ = 0;
  return r;
}

StepResult LumpedCavity::failed(const std::string& why) {
  ++statistics_.cutbacks;
  StepResult r;
  r.iterations = evaluations_;
  r.failure = why;
  evaluations_ = 0;
  return r;
}

StepResult LumpedCavity::try_volume_step(double volume_m3, const ProtocolLoads& loads) {
  try {
    pdet_ = wall_pressure(volume_m3, kRelaxedStep, loads.activation);  // held for long
  } catch (const std::runtime_error& e) {
    return failed(e.what());
  }
  pabd_ = loads.pabd_pa;
  return accept(volume_m3);
}

StepResult LumpedCavity::try_step(const StepRequest& step) {
  const double V_target = V0_ + step.infused_m3 + step.dt_s * step.inflow_m3_s - step.voided_m3;
  try {
    double V = V_target;
    if (step.urethra) V = voided_volume(V_target - (1.0 - kTheta) * step.dt_s * q_out_, step);
    pdet_ = wall_pressure(V, step.dt_s, step.loads.activation);
    pabd_ = step.loads.pabd_pa;
    const double q_new = step.urethra ? step.urethra->flow(pves()) : 0.0;
    StepResult r = accept(V);
    r.voided_m3 = step.urethra ? step.dt_s * (kTheta * q_new + (1.0 - kTheta) * q_out_) : 0.0;
    q_out_ = q_new;
    return r;
  } catch (const std::runtime_error& e) {
    return failed(e.what());
  }
}

// g(V) = V − V_base + θ dt Q(Pabd + Pdet(V)) is positive at V_base (the urethra can only
// drain) and increases with V wherever the wall's pressure does; the root is bracketed
// from below by steps down that double each time, then found by the Illinois variant of
// false position. Doubling bounds the bracketing where the slope of g is small: a
// contracting wall whose pressure rises as it shortens, or an abdomen that keeps the
// urethra open whatever the volume, would otherwise creep down in ever smaller steps.
double LumpedCavity::voided_volume(double V_base, const StepRequest& step) {
  const UrethraLaw& urethra = *step.urethra;
  const double dt = step.dt_s;
  auto g = [&](double V) {
    const double p = step.loads.pabd_pa + wall_pressure(V, dt, step.loads.activation);
    return V - V_base + kTheta * dt * urethra.flow(p);
  };
  double hi = V_base, g_hi = g(hi);
  if (g_hi <= 0.0) return hi;
  const double floor = 1e-3 * V_reference_;
  double down = g_hi;  // the root's distance below V_base where the slope of g is 1
  double lo = std::max(V_base - down, floor), g_lo = g(lo);
  while (g_lo > 0.0 && lo > floor) {
    hi = lo;
    g_hi = g_lo;
    down *= 2.0;
    lo = std::max(hi - down, floor);
    g_lo = g(lo);
  }
  if (g_lo > 0.0) throw std::runtime_error("voiding equation has no root above the floor");
  int side = 0;
  for (int it = 0; it < kMaxEvaluations; ++it) {
    const double V = (lo * g_hi - hi * g_lo) / (g_hi - g_lo);
    const double gV = g(V);
    if (std::abs(gV) <= kVolumeTolerance * V_base || hi - lo <= kVolumeTolerance * V_base) return V;
    if (gV > 0.0) {
      hi = V;
      g_hi = gV;
      if (side == 1) g_lo *= 0.5;
      side = 1;
    } else {
      lo = V;
      g_lo = gV;
      if (side == -1) g_hi *= 0.5;
      side = -1;
    }
  }
  throw std::runtime_error("voiding equation did not converge");
}

std::vector<Eigen::Vector3d> LumpedCavity::wall_positions() const {
  const double lambda = std::cbrt(std::max(volume_, 0.0) / V_drawn_);
  std::vector<Eigen::Vector3d> x(x_drawn_);
  for (Eigen::Vector3d& p : x) p = centre_drawn_ + lambda * (p - centre_drawn_);
  return x;
}

std::vector<MembraneStressOutput> LumpedCavity::wall_stresses() const {
  const double lambda = std::cbrt(volume_ / V_reference_);
  MembraneStressOutput s;
  const double J = std::sqrt(state_.J2);
  s.sigma1 = s.sigma2 = lambda * lambda * state_.S(0, 0) / J;  // σ = F S Fᵀ / J
  s.thickness = H_ * std::sqrt(state_.C33);
  s.stretch1 = s.stretch2 = lambda;
  std::vector<MembraneStressOutput> out(wall_.triangle_count(), s);
  for (std::size_t e = 0; e < out.size(); ++e)
    out[e].thickness = wall_.thickness[e] * std::sqrt(state_.C33);
  return out;
}

void LumpedCavity::add_summary(nlohmann::json& summary) const {
  if (taken_over_) {  // the tail of another level's voiding: its own key only
    summary["voiding_tail"]["pressure_scale"] = pressure_scale_;
    return;
  }
  summary["level"] = 0;
  summary["sphere_radius_mm"] = units::mm_from_m(R_);
  summary["sphere_thickness_mm"] = units::mm_from_m(H_);
}

}  // namespace vesica::simulate
