#include "protocol/CystometryProtocol.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

#include <nlohmann/json.hpp>

#include "protocol/Checkpoint.h"
#include "solver/StopRequest.h"
#include "vesica/core/Log.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/protocol/CystometrySummary.h"
#include "vesica/simulate/protocol/VtuSeriesWriter.h"

namespace vesica::simulate {
namespace {

// Volume per adaptive voiding step once the wall is slack (next_void_step): there every
// step is hard whatever its size, and small steps fail least.
constexpr double kSlackVoidStepMl = 1.0;
constexpr double kFirstVoidStepS = 0.1;  // the first adaptive voiding step
constexpr double kOpeningStepS = 0.01;   // the first adaptive step with the urethra open
// An adaptive voiding step changes the outflow by at most this fraction of the flow (or of
// the stop flow, when larger): the flow rises fast at the urethra's opening and falls at
// its closing, and is nearly steady on the plateau and in the tail.
constexpr double kFlowChangePerStep = 0.2;
constexpr double kHoldStepS = 10.0;  // the longest adaptive hold step
// An adaptive filling step grows by kFillGrowth after one that took at most
// kEasyIterations Newton iterations.
constexpr int kEasyIterations = 6;
constexpr double kFillGrowth = 1.5;
// The membrane has no contact: a voiding step never drains more than half of what is left
// above kVolumeFloorMl, so that the wall cannot collapse through itself; voiding stops
// below twice that.
constexpr double kVolumeFloorMl = 1.0;

// Volume change (cmH2O) below which an isovolumetric contraction has stopped rising.
constexpr double kStillPressureCmH2O = 0.01;
// Onset time constants after which the drive is at least 1 − e⁻⁵ ≈ 99.3 % activated.
constexpr double kFullOnsets = 5.0;

// The one-line reason of a run that stopped on a failed step (t in s, V in m³).
std::string step_failure_text(double t_s, double volume_m3, const std::string& reason) {
  std::ostringstream s;
  s.precision(6);
  s << "step failed at t = " << t_s << " s, V = " << units::ml_from_m3(volume_m3)
    << " ml: " << reason;
  return s.str();
}

// Why voiding cannot start at all, or "": straining needs a straining pressure.
std::string no_drive_note(const ProtocolSettings& settings) {
  if (settings.drive == VoidingDrive::Straining && settings.straining_kpa <= 0.0)
    return "no voiding: the drive is straining but straining_kpa is 0";
  return "";
}

// The progress line after a history row ("filling 120 ml") and the fraction of the
// protocol done (filling up to 0.8, voiding after).
std::pair<std::string, double> protocol_progress(const HistoryRow& row,
                                                 const ProtocolSettings& settings, bool voiding) {
  char step[64];
  if (!voiding) {
    const double span = settings.capacity_ml - settings.start_ml;
    const double done = span > 0.0 ? std::clamp(row.infused_ml / span, 0.0, 1.0) : 1.0;
    std::snprintf(step, sizeof step, "filling %.0f ml", row.volume_ml);
    return {step, 0.8 * done};
  }
  const double total = row.voided_ml + row.volume_ml;
  std::snprintf(step, sizeof step, "voiding %.0f ml", row.volume_ml);
  return {step, 0.8 + 0.2 * (total > 0.0 ? row.voided_ml / total : 1.0)};
}

}  // namespace

CystometryProtocol::CystometryProtocol(const ProtocolSettings& settings, const RunOptions& options)
    : settings_(settings),
      options_(options),
      urethra_(UrethraLaw::from_clinical_units(
          settings.p_open_cmh2o, settings.p_close_cmh2o, settings.r1_cmh2o_s_per_ml,
          settings.r2_cmh2o_s2_per_ml2, settings.urethra_half_open_cmh2o)),
      activation_{settings.activation_onset_s, settings.activation_plateau_s,
                  settings.activation_fade_s, settings.activation_delay_s} {}

CystometryProtocol::~CystometryProtocol() = default;

CystometryResult CystometryProtocol::run(CavityModel& model, const LevelLadder* ladder) {
  model_ = top_ = &model;
  ladder_ = ladder;
  rules_ = model.rules();
  if (!options_.output_dir.empty() && options_.write_series)
    series_ = std::make_unique<VtuSeriesWriter>(options_.output_dir);
  const auto start = std::chrono::steady_clock::now();
  auto lap = [last = start]() mutable {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - last).count();
    last = now;
    return s;
  };
  if (!options_.checkpoints.file.empty() && model.saves_state())
    checkpointer_ = std::make_unique<Checkpointer>(options_.checkpoints);
  try {
    if (!resume_if_asked()) {
      settle();
      phase_seconds_["settle"] = lap();
    }
    if (phase_ <= Phase::Filling) fill();
    if (settings_.hold_s > 0.0 && phase_ <= Phase::Hold) hold();
    phase_seconds_["filling"] += lap();
    capacity_index_ = result_.history.size() - 1;
    filled_ = true;
    phase_ = Phase::Voiding;
    if (settings_.void_after_fill && !options_.filling_only) void_bladder();
    phase_seconds_["voiding"] = lap();
    result_.completed = true;
  } catch (const StepFailed& e) {
    result_.failure = step_failure_text(time_, model_->volume(), e.what());
    // Failed while filling: every row is filling, none is voiding.
    if (!filled_ && !result_.history.empty()) capacity_index_ = result_.history.size() - 1;
    vesica::log()->error("{}", result_.failure);
  }
  take_notes();
  try {
    frame(true);
  } catch (const std::runtime_error& e) {
    // The wall's stresses at the last converged state may fail to evaluate where the step
    // after it failed (a tension field without a solution): the history and the summary
    // up to that state are still the run's results, and are written.
    if (result_.completed) throw;
    result_.notes.push_back(std::string("no last frame: ") + e.what());
  }
  if (series_) series_->finish();
  model.finish_frames();
  for (const auto& lower : lower_) lower->finish_frames();
  summarize(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return std::move(result_);
}

ProtocolLoads CystometryProtocol::loads_at(double t) const {
  const bool voiding = t_void_ >= 0.0;
  const double a = voiding ? activation_.at(t - t_void_) : 0.0;
  const bool straining = settings_.drive == VoidingDrive::Straining;
  const double pabd_cmh2o = voiding && !settings_.voiding_pabd.empty()
                                ? settings_.voiding_pabd.at(t - t_void_)
                                : settings_.pabd_cmh2o;
  return {units::pa_from_cmh2o(pabd_cmh2o) +
              (straining ? a * units::pa_from_kpa(settings_.straining_kpa) : 0.0),
          straining ? 0.0 : a};
}

// Gravity and the reference volume at t = 0, then up to the start volume, quasi-static.
void CystometryProtocol::settle() {
  const double target = units::m3_from_ml(settings_.start_ml);
  if (model_->needs_settling(target)) {
    step_to_volume(model_->volume());
    // From the stress-free reference the membrane has no stiffness out of its plane: a
    // full step there fails its Newton iterations, halving by halving, at the cost of a
    // whole failed Newton each (the most of a fine wall's run). So the moves start at a
    // sixteenth of the longest and double after every one that needed no cut-back.
    const double dv = units::m3_from_ml(options_.max_fill_step_ml);
    double move = dv / 16.0;
    while (std::abs(model_->volume() - target) > 1e-12 * target) {
      const double next = model_->volume() + std::clamp(target - model_->volume(), -move, move);
      move = step_to_volume(next) == 0 ? std::min(dv, 2.0 * move) : move;
    }
  }
  model_->start_clock();
  time_ = 0.0;
  infused_ = voided_ = 0.0;
  start_volume_ = model_->volume();
  record();
}

int CystometryProtocol::step_to_volume(double V) {
  std::string failure;
  for (int cut = 0; cut <= rules_.max_settle_cutbacks; ++cut) {
    const double target = model_->volume() + (V - model_->volume()) / std::pow(2.0, cut);
    const StepResult r = model_->try_volume_step(target, loads_at(time_));
    if (r.converged) {
      // the rest of the way from the shorter move
      return cut > 0 ? cut + step_to_volume(V) : 0;
    }
    failure = r.failure;
  }
  if (checkpointer_) checkpointer_->stop_if_signalled();  // settling: before any checkpoint
  throw StepFailed("no equilibrium at " + std::to_string(units::ml_from_m3(V)) + " ml (" + failure +
                   ")");
}

StepResult CystometryProtocol::advance(double dt, double q_in, bool outlet) {
  std::string failure;
  int cut = 0;
  // The state before this step: a stop during it is checkpointed here, the last step done.
  const std::optional<CheckpointWriter> before = last_step_state();
  for (;; ++cut, dt *= 0.5) {
    StepRequest step;
    step.dt_s = dt;
    step.end_time_s = time_ + dt;
    step.inflow_m3_s = q_in;
    // The sphincter's recovery at the volume the step starts from.
    if (outlet && volume_at_opening_ > 0.0)
      urethra_now_ = urethra_.recovering(settings_.urethra_recovery_half,
                                         1.0 - model_->volume() / volume_at_opening_);
    step.urethra = outlet ? &urethra_now_ : nullptr;
    step.loads = loads_at(time_ + dt);
    step.infused_m3 = infused_;
    step.voided_m3 = voided_;
    StepResult r = model_->try_step(step);
    take_notes();
    if (r.converged) {
      time_ += dt;
      infused_ += dt * q_in;
      voided_ += r.voided_m3;
      return r;
    }
    failure = r.failure;
    if (checkpointer_ && stop_requested()) {  // the model is back where the step began
      write_checkpoint_of(before);
      checkpointer_->stop_if_signalled();
    }
    if (cut == rules_.max_cutbacks) break;
    // While voiding, a step at the shortest cut-back step fails at once.
    if (voiding_ && dt < 2.0 * rules_.min_cut_void_step_s) {
      failure += ", at the shortest voiding step";
      break;
    }
  }
  throw StepFailed(failure + " after " + std::to_string(cut) + " step cut-backs");
}

void CystometryProtocol::fill() {
  const double q_in = units::m3s_from_ml_per_min(settings_.fill_rate_ml_min);
  const double target = units::m3_from_ml(settings_.capacity_ml - settings_.start_ml);
  const double dt_max = units::m3_from_ml(options_.max_fill_step_ml) / q_in;
  double dt = rules_.fixed_fill_step_s > 0.0 ? rules_.fixed_fill_step_s : dt_max / 2;
  if (std::exchange(resuming_, false)) dt = step_s_;
  phase_ = Phase::Filling;
  while (infused_ < target * (1.0 - 1e-12)) {
    if (rules_.fixed_fill_step_s > 0.0) dt = rules_.fixed_fill_step_s;
    dt = std::min(dt, (target - infused_) / q_in);
    const int iterations = advance(dt, q_in, false).iterations;
    record();
    if (settings_.fill_limit_cmh2o > 0.0 &&
        result_.history.back().pdet_cmh2o >= settings_.fill_limit_cmh2o)
      break;
    // An adaptive step grows after an easy one (from the step asked: a cut-back step says
    // only that this point was hard).
    if (rules_.fixed_fill_step_s <= 0.0 && iterations <= kEasyIterations)
      dt = std::min(kFillGrowth * dt, dt_max);
    step_s_ = dt;
    checkpoint_if_due();
  }
}

void CystometryProtocol::hold() {
  if (!std::exchange(resuming_, false)) {
    hold_end_s_ = time_ + settings_.hold_s;
    step_s_ = rules_.fixed_fill_step_s > 0.0 ? rules_.fixed_fill_step_s
                                             : std::min(settings_.hold_s, kHoldStepS);
  }
  phase_ = Phase::Hold;
  const double t_end = hold_end_s_;
  double dt = step_s_;
  while (time_ < t_end - 1e-9) {
    dt = std::min(dt, t_end - time_);
    advance(dt, 0.0, false);
    record();
    step_s_ = dt;
    checkpoint_if_due();
  }
}

// The drive is activated from the end of filling; the urethra opens once Pves reaches
// p_open (an isovolumetric contraction until then), passes its law's flow and closes at
// p_close. Voiding ends when the flow, once above stop_flow_ml_s, falls below it (closing
// included), when the contraction can no longer open the urethra, or after max_void_s.
void CystometryProtocol::void_bladder() {
  if (const std::string why = no_drive_note(settings_); !why.empty()) {
    result_.notes.push_back(why);
    vesica::log()->warn("{}", why);
    return;
  }
  voiding_ = true;
  t_void_ = time_;
  next_frame_ = time_;
  const bool adaptive = rules_.fixed_void_step_s <= 0.0;
  double dt = adaptive ? kFirstVoidStepS : rules_.fixed_void_step_s;
  bool flowing = false;
  const double stop = units::m3s_from_mls(settings_.stop_flow_ml_s);
  const double V_floor = units::m3_from_ml(kVolumeFloorMl);
  peak_pves_ = model_->pves();
  while (time_ - t_void_ < settings_.max_void_s) {
    if (!urethra_open_ && model_->pves() >= urethra_.opening_pressure()) {
      urethra_open_ = true;
      volume_at_opening_ = model_->volume();
      model_->urethra_opens(urethra_);
      // The flow starts from zero: a step grown through the isovolumetric contraction
      // would jump over its rise (and the pressure could fall below p_close in one step).
      if (adaptive && rules_.void_step_follows_flow)
        dt = std::max(rules_.min_void_step_s, kOpeningStepS);
    }
    const double V_before = model_->volume(), t_before = time_, p_before = model_->pves();
    const double Q_before = model_->outflow();
    if (!adaptive) dt = rules_.fixed_void_step_s;
    if (model_->outflow() > 0.0) dt = std::min(dt, 0.5 * (V_before - V_floor) / model_->outflow());
    const double dt_asked = dt;
    int iterations = 0;
    try {
      iterations = advance(dt, 0.0, urethra_open_).iterations;
    } catch (const StepFailed& e) {
      // With the urethra open the level below may go on (LevelLadder.h); the same step is
      // tried again on it.
      if (urethra_open_ && options_.hand_over && hand_over(e.what())) continue;
      std::string note = model_->voiding_end_note(e.what());
      if (note.empty() && urethra_open_ && !options_.hand_over)
        note = "voiding ended at " + std::to_string(units::ml_from_m3(model_->volume())) +
               " ml, where the wall could not take a step (" + e.what() +
               "), the hand-over to a simpler level being off";
      if (note.empty()) throw;
      result_.notes.push_back(note);
      vesica::log()->warn("{}", note);
      break;
    }
    record();
    if (checkpointer_) checkpointer_->stop_if_signalled();  // no checkpoints while voiding
    peak_pves_ = std::max(peak_pves_, model_->pves());
    const double Q = model_->outflow();
    if (urethra_open_) {
      if (Q >= stop) flowing = true;
      if ((flowing && Q < stop) || Q <= 0.0) break;  // the flow stopped, or the urethra closed
    } else if (contraction_spent(p_before)) {
      break;
    }
    if (model_->volume() < 2.0 * V_floor) break;
    if (!adaptive) continue;
    // From the step actually taken: a cut-back shortened it. A cut-back says the step size
    // is at its limit here: grow again only slowly (a 2x growth right after it failed
    // again on the crumpling wall, every other step).
    const double dt_taken = time_ - t_before;
    max_growth_ = dt_taken < dt_asked * (1.0 - 1e-9) ? 1.0 : std::min(2.0, 1.25 * max_growth_);
    dt = next_void_step(dt_taken, std::abs(V_before - model_->volume()),
                        std::abs(Q - Q_before) / std::max({Q, Q_before, stop}), iterations);
  }
  if (!urethra_open_) {
    std::ostringstream note;
    note.precision(3);
    note << "no voiding: Pves peaked at " << units::cmh2o_from_pa(peak_pves_)
         << " cmH2O, below the opening pressure of " << settings_.p_open_cmh2o << " cmH2O ("
         << drive_name(settings_.drive) << " drive)";
    result_.notes.push_back(note.str());
    vesica::log()->warn("{}", note.str());
  }
}

// Whether a drive that has not opened the urethra never will: fully activated (or fading)
// and Pves no longer rising over the last step (p_before: Pves before it), and no recorded
// abdominal pressure still to come.
bool CystometryProtocol::contraction_spent(double p_before) const {
  const double t = time_ - t_void_;
  if (!settings_.voiding_pabd.empty() && t < settings_.voiding_pabd.time_s.back()) return false;
  const double active = t - settings_.activation_delay_s;  // since the drive's onset
  const bool full = active >= kFullOnsets * settings_.activation_onset_s;
  const bool fading = active > settings_.activation_plateau_s;
  const bool still = model_->pves() - p_before < units::pa_from_cmh2o(kStillPressureCmH2O);
  return fading || (full && still);
}

// Aim at a volume per step, growing at most max_growth_ (2x, less after a cut-back). A taut
// wall drains smoothly (2 Newton iterations a step with the model's predictor), so the aim
// is a quarter of the volume left above the stress-free reference, up to max_void_step_ml;
// near and below the reference the wall goes slack and wrinkles, every step is hard
// whatever its size, and small steps fail least. When the model asks (level 2,
// StepRules::void_step_follows_flow) the step also keeps the flow's relative change per
// step (flow_change, of the step just taken) near kFlowChangePerStep (backward Euler's
// error follows the change of the solution per step), and does not grow after a step whose
// Newton needed more than kEasyIterations. Within the model's bounds.
double CystometryProtocol::next_void_step(double dt, double dV, double flow_change,
                                          int iterations) const {
  const double slack_aim = units::m3_from_ml(
      rules_.slack_void_step_ml > 0.0 ? rules_.slack_void_step_ml : kSlackVoidStepMl);
  const double taut_aim = units::m3_from_ml(rules_.void_step_ml > 0.0 ? rules_.void_step_ml
                                                                      : options_.max_void_step_ml);
  const double aim = std::clamp((model_->volume() - model_->reference_volume()) / 4.0, slack_aim,
                                std::max(slack_aim, taut_aim));
  const bool by_flow = rules_.void_step_follows_flow;
  const double growth = by_flow && iterations > kEasyIterations ? 1.0 : max_growth_;
  double next = dV > 0.0 ? std::clamp(dt * aim / dV, 0.5 * dt, growth * dt) : growth * dt;
  if (by_flow && flow_change > 0.0)
    next = std::min(next, std::clamp(dt * kFlowChangePerStep / flow_change, 0.5 * dt, growth * dt));
  const double longest =
      rules_.max_void_step_s > 0.0 ? rules_.max_void_step_s : options_.max_void_step_s;
  return std::clamp(next, std::min(rules_.min_void_step_s, longest), longest);
}

void CystometryProtocol::record() {
  HistoryRow row;
  row.time_s = time_;
  row.infused_ml = units::ml_from_m3(infused_);
  row.volume_ml = units::ml_from_m3(model_->volume());
  row.pves_cmh2o = units::cmh2o_from_pa(model_->pves());
  row.pabd_cmh2o = units::cmh2o_from_pa(loads_at(time_).pabd_pa);
  row.pdet_cmh2o = row.pves_cmh2o - row.pabd_cmh2o;
  row.flow_ml_s = std::max(0.0, units::mls_from_m3s(model_->outflow()));
  row.voided_ml = units::ml_from_m3(voided_);
  result_.history.push_back(row);
  if (options_.on_progress) {
    const auto [step, fraction] = protocol_progress(row, settings_, voiding_);
    options_.on_progress(step + progress_label(), fraction);
  }
  const double expected = start_volume_ + infused_ - voided_;
  mass_error_ = std::max(mass_error_, std::abs(model_->volume() - expected) / expected);
  frame(false);
}

void CystometryProtocol::frame(bool force) {
  if (!force && time_ + 1e-9 < next_frame_) return;
  const auto stresses = model_->wall_stresses();
  for (const auto& s : stresses) max_stress_ = std::max(max_stress_, s.sigma1);
  const bool write = series_ && (force ? last_frame_ < time_ : true);
  if (write)
    series_->add_step(time_,
                      {units::ml_from_m3(model_->volume()),
                       units::cmh2o_from_pa(model_->pves() - loads_at(time_).pabd_pa)},
                      model_->wall(), model_->wall_positions(), stresses);
  model_->add_frame(time_, write);
  last_frame_ = time_;
  next_frame_ = time_ + (voiding_ ? rules_.void_frame_interval_s : options_.series_interval_s);
}

bool CystometryProtocol::hand_over(const std::string& failure) {
  if (!ladder_) return false;
  LevelLadder::Step next = ladder_->below(*model_, failure);
  if (!next.model) return false;
  const double volume_ml = units::ml_from_m3(model_->volume());
  result_.card.hand_overs.push_back(
      {model_->level(), next.model->level(), volume_ml, time_, next.reason});
  std::ostringstream note;
  note.precision(4);
  note << level_name(model_->level()) << " could not go on at V = " << volume_ml
       << " ml, t = " << time_ << " s: " << next.reason << "; from there the voiding ran on "
       << level_name(next.model->level());
  result_.notes.push_back(note.str());
  vesica::log()->warn("{}", note.str());
  lower_.push_back(std::move(next.model));
  model_ = lower_.back().get();
  // The level below steps by its own rules, as a run started there would.
  rules_ = model_->rules();
  take_notes();
  return true;
}

// Where the run changed level, in the summary keys users and tests read: level1_from
// (2 → 1: time and volume; null for a level-2 run that voided to the end alone) and
// voiding_tail (→ 0: from where and why).
void CystometryProtocol::summarize_hand_overs(nlohmann::json& s) const {
  if (top_->level() == 2) s["level1_from"] = nullptr;
  for (const LevelHandOver& h : result_.card.hand_overs) {
    if (h.from == 2 && h.to == 1)
      s["level1_from"] = {{"time_s", h.time_s}, {"volume_ml", h.volume_ml}};
    if (h.to == 0)
      s["voiding_tail"] = {{"model", level_name(0)},
                           {"from_level", h.from},
                           {"from_ml", h.volume_ml},
                           {"wall_failure", h.reason}};
  }
}

std::string CystometryProtocol::progress_label() const {
  const std::string own = model_->progress_label();
  if (result_.card.hand_overs.empty() || !own.empty()) return own;
  return " (level " + std::to_string(model_->level()) + ")";
}

void CystometryProtocol::take_notes() {
  for (std::string& note : model_->take_notes()) result_.notes.push_back(std::move(note));
}

void CystometryProtocol::summarize(double seconds) {
  nlohmann::json& s = result_.summary;
  s["completed"] = result_.completed;
  if (!result_.notes.empty()) s["notes"] = result_.notes;
  if (!result_.completed) s["failure"] = result_.failure;
  s["triangles"] = top_->wall().triangle_count();
  s["nodes"] = top_->wall().node_count();
  s["reference_volume_ml"] = units::ml_from_m3(top_->reference_volume());
  summarize_history(result_.history, capacity_index_, s);
  s["max_wall_stress_kpa"] = units::kpa_from_pa(max_stress_);
  s["mass_balance_error_max_rel"] = mass_error_;
  s["newton"] = top_->statistics();
  for (const auto& lower : lower_) {  // the levels handed down to
    nlohmann::json level = lower->statistics();
    level["level"] = lower->level();
    s["newton"]["after_hand_over"].push_back(std::move(level));
  }
  s["compute_s"] = seconds;
  s["phase_compute_s"] = phase_seconds_;
  s["outlet"] = {{"p_open_cmh2o", settings_.p_open_cmh2o},
                 {"p_close_cmh2o", settings_.p_close_cmh2o},
                 {"r1_cmh2o_s_per_ml", settings_.r1_cmh2o_s_per_ml},
                 {"r2_cmh2o_s2_per_ml2", settings_.r2_cmh2o_s2_per_ml2},
                 {"half_open_cmh2o", settings_.urethra_half_open_cmh2o},
                 {"recovery_half", settings_.urethra_recovery_half}};
  // What emptied the bladder: the drive when the urethra opened, else none.
  s["voiding_drive"] = urethra_open_ ? drive_name(settings_.drive) : "none";
  // What the abdomen did while voiding: the recording's Pabd replayed, or at rest
  // (straining included in the drive's name).
  if (voiding_) s["voiding_pabd"] = settings_.voiding_pabd.empty() ? "resting" : "recorded";
  if (voiding_) s["pves_max_voiding_cmh2o"] = units::cmh2o_from_pa(peak_pves_);
  top_->add_summary(s);
  summarize_hand_overs(s);
  for (const auto& lower : lower_) lower->add_summary(s);
}

}  // namespace vesica::simulate
