// --calibrate from the command line: the wall from --mesh, the protocol from the measured
// recording (its fill rate, its abdominal pressure at capacity), the data from the
// recording's filling (--fit-volume-ml, default from --start-ml to capacity) and, when a
// voiding parameter is fitted, its voiding.
#include <algorithm>
#include <sstream>

#include <fmt/format.h>

#include "vesica/compare/calibration/Calibration.h"
#include "vesica/compare/calibration/CalibrationRun.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/protocol/PressureTrace.h"

namespace vesica::compare {
namespace {

constexpr double kStandardFillRateMlMin = 50.0;  // ICS medium filling, docs/physics.md §7.1

// The default bladder wall's passive parameters (docs/simulate.md "Default walls"): the
// start of a fit of the detrusor-voided model, whose wall is that one.
constexpr double kBladderMuKpa = 1.0, kBladderK1Pa = 60.0, kBladderK2 = 0.045;

std::vector<ModelParameter> parse_parameters(const std::string& list, const CalibrationModel& m,
                                             bool bladder) {
  std::vector<ModelParameter> specs;
  std::stringstream ss(list);
  for (std::string name; std::getline(ss, name, ',');) {
    if (name.empty()) continue;
    ModelParameter s = model_parameter(name);
    double& start = s.fit.initial;
    if (name == "mu") start = bladder ? kBladderMuKpa : m.mu_kpa;
    if (name == "k1" && bladder) start = kBladderK1Pa;
    if (name == "k2" && bladder) start = kBladderK2;
    if (name == "k" && m.k_kpa > 0) start = m.k_kpa;
    if (name == "straining" && m.straining_kpa > 0) start = m.straining_kpa;
    if (name == "detrusor" && m.detrusor_kpa > 0) start = m.detrusor_kpa;
    start = std::clamp(start, s.fit.lower, s.fit.upper);
    specs.push_back(s);
  }
  if (specs.empty()) usage_error("--calibrate: no parameter named");
  return specs;
}

bool fits(const std::vector<ModelParameter>& specs, const char* name) {
  return std::any_of(specs.begin(), specs.end(), [&](const auto& s) { return s.fit.name == name; });
}

// The drive that voids the model: straining when it is fitted or given, else the detrusor.
bool strains(const std::vector<ModelParameter>& specs, const CalibrationModel& m) {
  return fits(specs, "straining") || m.straining_kpa > 0;
}

std::string material_for(const std::vector<ModelParameter>& specs, const CalibrationModel& m,
                         bool voiding) {
  // A detrusor-voided model needs a muscle: the default bladder wall (docs/simulate.md).
  if (voiding && !strains(specs, m)) return "bladder";
  if (fits(specs, "k1") || fits(specs, "k2")) return "fibers";
  if (fits(specs, "beta") || fits(specs, "tau")) return "maxwell";
  return "neo-hookean";
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
  double lo = o.simulation.start_ml, hi = o.simulation.start_ml;
  if (!a.filling.x.empty()) {
    lo = std::max(*std::min_element(a.filling.x.begin(), a.filling.x.end()), o.simulation.start_ml);
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
  if (t.capacity_ml <= o.simulation.start_ml)
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

CystometryModel model_for(const CompareOptions& o, const RecordingAnalysis& a,
                          const std::vector<ModelParameter>& specs, bool voiding,
                          std::vector<std::string>& notes) {
  CystometryModel m;
  m.material.name = material_for(specs, o.simulation, voiding);
  simulate::WallOptions wall_options;
  wall_options.thickness_mm = o.simulation.thickness_mm;
  // The bladder wall is stress-free at its own residual volume (WallOptions' default, below
  // the start of filling: docs/simulate.md "Default walls"), so that it starts filling at a
  // positive Pdet and can void below the start volume while taut; the plain laws at the
  // start volume, as the filling-only fits always were.
  if (m.material.name != "bladder") wall_options.residual_ml = o.simulation.start_ml;
  m.wall = simulate::load_wall(o.mesh, wall_options);
  // The bladder wall keeps its own passive parameters unless fitted.
  if (m.material.name != "bladder")
    m.material.params = {{"mu", units::pa_from_kpa(o.simulation.mu_kpa)}};
  if (o.simulation.k_kpa > 0.0)
    m.material.params["K"] = units::pa_from_kpa(o.simulation.k_kpa);
  else
    m.material.params["K_per_mu"] = 1e3;  // nearly incompressible, as vesica-simulate
  m.protocol.start_ml = o.simulation.start_ml;
  // Without gravity: a stress-free membrane at the start volume carries its own weight
  // with no stiffness (no equilibrium), and the measured Pdet is referred to the
  // catheter, not to a hydrostatic column.
  m.protocol.gravity = false;
  m.protocol.fill_rate_ml_min = fill_rate(o, a, notes);
  // The urethra opens on Pves = Pdet + Pabd: the model's abdomen at the recording's.
  const auto& r = a.recording;
  if (!r.pabd_cmh2o.empty())
    m.protocol.pabd_cmh2o = std::max(0.0, r.pabd_cmh2o[a.ics.capacity_row]);
  if (voiding && !strains(specs, o.simulation)) {
    m.protocol.voiding_pabd = recorded_voiding_pabd(a);
    if (!m.protocol.voiding_pabd.empty())
      notes.push_back(fmt::format(
          "while voiding the model's abdominal pressure is the recording's ({} readings from "
          "capacity on): the detrusor makes Pdet, the patient's straining adds to Pves",
          m.protocol.voiding_pabd.time_s.size()));
  }
  if (strains(specs, o.simulation)) {
    m.protocol.drive = simulate::VoidingDrive::Straining;
    if (o.simulation.straining_kpa > 0) m.protocol.straining_kpa = o.simulation.straining_kpa;
  }
  if (o.simulation.detrusor_kpa > 0)
    m.material.params["contractility"] = units::pa_from_kpa(o.simulation.detrusor_kpa);
  return m;
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
  CalibrationProblem pb;
  const std::vector<ModelParameter> named = parse_parameters(o.calibrate, o.simulation, false);
  const bool voiding = std::any_of(named.begin(), named.end(),
                                   [](const ModelParameter& p) { return p.fit.voiding; });
  pb.parameters = parse_parameters(o.calibrate, o.simulation,
                                   material_for(named, o.simulation, voiding) == "bladder");
  pb.targets = targets_for(o, a, comparison, voiding);
  std::vector<std::string> notes;
  pb.model = model_for(o, a, pb.parameters, voiding, notes);
  if (a.ics.capacity_ml) pb.data_end_ml = *a.ics.capacity_ml;
  pb.use_surrogate = o.simulation.surrogate;
  pb.budget.surrogate_starts = o.simulation.surrogate_starts;
  pb.budget.model_simulations = o.max_simulations;
  FitOutcome out = voiding && mixes_filling_and_voiding(pb.parameters)
                       ? fit_filling_then_voiding(pb, targets_for(o, a, comparison, false))
                       : calibrate(pb);
  if (voiding && out.final_run.recording.rows() > 0)
    out.result.voiding = voiding_agreement(a, out.final_run.recording);
  notes.push_back(fmt::format("the model fills at {:.3g} ml/min from {:g} ml",
                              pb.model.protocol.fill_rate_ml_min, pb.model.protocol.start_ml));
  out.result.notes.insert(out.result.notes.begin(), notes.begin(), notes.end());
  return out.result;
}

}  // namespace vesica::compare
