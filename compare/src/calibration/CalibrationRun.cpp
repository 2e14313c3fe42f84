// --calibrate from the command line: the model vesica-simulate would run with the same
// options (the material, default the bladder wall, its own parameters and stress-free
// volume) on the wall from --mesh, the protocol from the measured recording (its fill rate,
// its abdominal pressure at capacity), the data from the recording's filling
// (--fit-volume-ml, default from --start-ml to capacity) and, when a voiding parameter is
// fitted, its voiding. Each fitted parameter starts from that model's value.
#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "vesica/compare/calibration/Calibration.h"
#include "vesica/compare/calibration/CalibrationRun.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/ParameterCatalogue.h"
#include "vesica/simulate/SimulateParameters.h"
#include "vesica/simulate/protocol/PressureTrace.h"

namespace vesica::compare {
namespace {

constexpr double kStandardFillRateMlMin = 50.0;  // ICS medium filling, docs/physics.md §7.1

// The value a fitted parameter starts from: the model's own (given, or the material's
// default), unless that lies on or outside the search's bounds, where the catalogue's
// start (or the nearest bound) is taken.
double start_value(const simulate::PhysicalParameter& p, const simulate::ModelCard& model) {
  std::vector<double> si = simulate::card_value_si(model, p);
  // A material without a Maxwell branch fits the thesis's branch (the maxwell material's).
  if (si.empty() && p.per_branch) si = p.default_si("maxwell");
  if (si.empty())
    usage_error("--calibrate " + p.name + ": material " + model.material.name + " has no " + p.name,
                "choose a --material that has it (docs/parameters.md)");
  const double v = si.front() / p.si_per_unit;
  const simulate::FitRange& r = *p.fit_range;
  if (v > r.lower && v < r.upper) return v;
  return p.fit_start ? *p.fit_start : std::clamp(v, r.lower, r.upper);
}

std::vector<ModelParameter> parse_parameters(const std::string& list,
                                             const simulate::ModelCard& model) {
  std::vector<ModelParameter> specs;
  std::stringstream ss(list);
  for (std::string name; std::getline(ss, name, ',');) {
    if (name.empty()) continue;
    ModelParameter s = model_parameter(name);
    s.fit.initial = start_value(simulate::catalogue_parameter(s.fit.name), model);
    specs.push_back(s);
  }
  if (specs.empty()) usage_error("--calibrate: no parameter named");
  return specs;
}

bool fits(const std::vector<ModelParameter>& specs, const char* name) {
  return std::any_of(specs.begin(), specs.end(), [&](const auto& s) { return s.fit.name == name; });
}

// The drive that voids the model: straining when it is fitted or asked for (--drive).
bool strains(const std::vector<ModelParameter>& specs, const simulate::ProtocolSettings& p) {
  return fits(specs, "straining") || p.drive == simulate::VoidingDrive::Straining;
}

// The fill rate the model fills at: given, else inferred from the recording, else ICS's
// standard medium rate (said in the notes).
double fill_rate(const CompareOptions& o, const RecordingAnalysis& a,
                 std::vector<std::string>& notes) {
  if (o.fill_rate_ml_min > 0) return o.fill_rate_ml_min;
  if (a.ics.fill_rate_ml_min) return *a.ics.fill_rate_ml_min;
  notes.push_back(
      "the recording gives no fill rate: the model fills at the standard 50 ml/min "
      "(give --fill-rate-ml-min)");
  return kStandardFillRateMlMin;
}

CalibrationTargets targets_for(const CompareOptions& o, const RecordingAnalysis& a,
                               const ComparisonOptions& comparison, bool voiding) {
  double lo = o.simulation.model.protocol.start_ml, hi = o.simulation.model.protocol.start_ml;
  if (!a.filling.x.empty()) {
    lo = std::max(*std::min_element(a.filling.x.begin(), a.filling.x.end()),
                  o.simulation.model.protocol.start_ml);
    hi = *std::max_element(a.filling.x.begin(), a.filling.x.end());
  }
  if (comparison.volume_range_ml) {
    lo = std::max(lo, comparison.volume_range_ml->first);
    hi = std::min(hi, comparison.volume_range_ml->second);
  }
  CalibrationTargets t = filling_targets(a, lo, hi);
  if (voiding && !add_voiding_targets(a, t))
    usage_error(
        "--calibrate: voiding parameters need a voiding phase (flow or voided volume) "
        "in the measured recording");
  if (t.series.empty() || t.size() < 2)
    usage_error("--calibrate: the measured recording has fewer than two readings to fit",
                "check --fit-volume-ml and --start-ml against the recording's volumes");
  if (t.capacity_ml <= o.simulation.model.protocol.start_ml)
    usage_error(
        fmt::format("--calibrate: the data end at {:g} ml, not above --start-ml", t.capacity_ml),
        "lower --start-ml");
  return t;
}

// The recording's abdominal pressure from capacity to its last row, against the time
// since capacity: what a detrusor-voided model replays while it voids, so that a patient's
// straining raises the model's Pves as it raised hers and the detrusor makes only Pdet.
// Empty without time or Pabd.
simulate::PressureTrace recorded_voiding_pabd(const RecordingAnalysis& a) {
  simulate::PressureTrace trace;
  const io::Recording& r = a.recording;
  if (!r.has_time() || r.pabd_cmh2o.empty()) return trace;
  const double t0 = r.time_s[a.ics.capacity_row];
  for (std::size_t i = a.ics.capacity_row; i < r.rows(); ++i) {
    const double t = r.time_s[i] - t0;
    if (!trace.empty() && !(t > trace.time_s.back())) continue;  // a repeated time stamp
    trace.time_s.push_back(t);
    trace.cmh2o.push_back(std::max(0.0, r.pabd_cmh2o[i]));
  }
  if (trace.time_s.size() < 2) return {};
  return trace;
}

// The model vesica-simulate would run with the same options (the material's own parameters
// unless given, its stress-free volume), set to the recording: its fill rate, its abdominal
// pressure at capacity, and, for a detrusor-voided model, its abdominal pressure while
// voiding. Without gravity: the measured Pdet is referred to the catheter, not to a
// hydrostatic column (said on the card).
CystometryModel model_for(const CompareOptions& o, const RecordingAnalysis& a,
                          std::vector<std::string>& notes) {
  const simulate::SimulateSettings& s = o.simulation.model;
  CystometryModel m;
  m.material = simulate::material_spec(s.material);
  simulate::WallOptions wall_options = s.wall;
  wall_options.posture = s.posture;
  m.wall = simulate::load_wall(o.mesh, wall_options);
  m.protocol = s.protocol;
  m.protocol.posture = s.posture;
  m.protocol.gravity = false;
  m.run.hand_over = s.run.hand_over;
  m.protocol.fill_rate_ml_min = fill_rate(o, a, notes);
  // The urethra opens on Pves = Pdet + Pabd: the model's abdomen at the recording's.
  const auto& r = a.recording;
  if (!r.pabd_cmh2o.empty())
    m.protocol.pabd_cmh2o = std::max(0.0, r.pabd_cmh2o[a.ics.capacity_row]);
  return m;
}

// A detrusor-voided model replays the recording's abdominal pressure while it voids.
void replay_voiding_pabd(const RecordingAnalysis& a, CystometryModel& m,
                         std::vector<std::string>& notes) {
  m.protocol.voiding_pabd = recorded_voiding_pabd(a);
  if (!m.protocol.voiding_pabd.empty())
    notes.push_back(fmt::format(
        "while voiding the model's abdominal pressure is the recording's ({} readings from "
        "capacity on): the detrusor makes Pdet, the patient's straining adds to Pves",
        m.protocol.voiding_pabd.time_s.size()));
}

// Whether the fit has both the wall's passive parameters and the voiding's.
bool mixes_filling_and_voiding(const std::vector<ModelParameter>& params) {
  const auto voiding = [](const ModelParameter& p) { return p.fit.voiding; };
  return std::any_of(params.begin(), params.end(), voiding) &&
         !std::all_of(params.begin(), params.end(), voiding);
}

// One fit's stages, parameters and counts after another's (the first one's stages named
// after its phase).
void prepend(const CalibrationResult& first, const std::string& phase, CalibrationResult& r) {
  std::vector<CalibrationStage> stages = first.stages;
  for (auto& s : stages) s.name = phase + ": " + s.name;
  r.stages.insert(r.stages.begin(), stages.begin(), stages.end());
  r.parameters.insert(r.parameters.begin(), first.parameters.begin(), first.parameters.end());
  r.simulations += first.simulations;
  r.failed_simulations += first.failed_simulations;
  r.iterations += first.iterations;
  r.seconds += first.seconds;
  for (const std::string& n : first.notes) r.notes.push_back(phase + ": " + n);
}

// The wall's passive parameters from the filling alone, then the voiding's with them held
// (docs/compare.md, "Filling, then voiding"): the voiding readings, many more and scaled
// more loosely, would otherwise bend the filling curve to help the voiding fit, and the
// passive wall is what the filling measures.
FitOutcome fit_filling_then_voiding(CalibrationProblem pb, const CalibrationTargets& filling) {
  CalibrationProblem passive = pb;
  passive.parameters.clear();
  std::vector<ModelParameter> active;
  for (const ModelParameter& p : pb.parameters)
    (p.fit.voiding ? active : passive.parameters).push_back(p);
  passive.targets = filling;
  passive.model.protocol.void_after_fill = false;
  const FitOutcome first = calibrate(passive);
  if (first.result.parameters.size() != passive.parameters.size() ||
      first.final_run.recording.rows() == 0)
    return first;
  for (std::size_t i = 0; i < passive.parameters.size(); ++i)
    passive.parameters[i].apply(first.result.parameters[i].value, pb.model.material,
                                pb.model.protocol);
  pb.parameters = active;
  FitOutcome out = calibrate(pb);
  prepend(first.result, "filling", out.result);
  out.result.notes.insert(
      out.result.notes.begin(),
      "the wall's passive parameters were fitted to the filling alone, then held while the "
      "voiding parameters were fitted to the whole recording; their intervals are the "
      "filling fit's");
  return out;
}

}  // namespace

CalibrationResult calibrate_from_options(const CompareOptions& o, const RecordingAnalysis& a,
                                         const ComparisonOptions& comparison) {
  std::vector<std::string> notes;
  CalibrationProblem pb;
  pb.model = model_for(o, a, notes);
  // The model as it starts: every parameter's value, given or the material's own.
  const simulate::ModelCard start = simulate::planned_model_card(pb.model.wall, pb.model.material,
                                                                 pb.model.protocol, pb.model.run);
  pb.parameters = parse_parameters(o.calibrate, start);
  const bool voiding = std::any_of(pb.parameters.begin(), pb.parameters.end(),
                                   [](const ModelParameter& p) { return p.fit.voiding; });
  if (voiding && strains(pb.parameters, pb.model.protocol))
    pb.model.protocol.drive = simulate::VoidingDrive::Straining;
  else if (voiding)
    replay_voiding_pabd(a, pb.model, notes);
  pb.targets = targets_for(o, a, comparison, voiding);
  if (a.ics.capacity_ml) pb.data_end_ml = *a.ics.capacity_ml;
  pb.use_surrogate = o.simulation.surrogate;
  pb.budget.surrogate_starts = o.simulation.surrogate_starts;
  pb.budget.model_simulations = o.max_simulations;
  FitOutcome out = voiding && mixes_filling_and_voiding(pb.parameters)
                       ? fit_filling_then_voiding(pb, targets_for(o, a, comparison, false))
                       : calibrate(pb);
  if (voiding && out.final_run.recording.rows() > 0)
    out.result.voiding = voiding_agreement(a, out.final_run.recording);
  out.result.fitted_card = out.final_run.card;
  notes.push_back(fmt::format(
      "the model fills at {:.3g} ml/min from {:g} ml; material {} ({}), "
      "stress-free at {:g} ml",
      pb.model.protocol.fill_rate_ml_min, pb.model.protocol.start_ml, start.material.name,
      simulate::material_text(start.material), start.reference_volume_ml));
  out.result.notes.insert(out.result.notes.begin(), notes.begin(), notes.end());
  return out.result;
}

}  // namespace vesica::compare
