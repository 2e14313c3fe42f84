#include "vesica/compare/calibration/Calibration.h"

#include <algorithm>
#include <cmath>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Units.h"

namespace vesica::compare {
namespace {

using Apply = std::function<void(double, simulate::MaterialSpec&, simulate::ProtocolSettings&)>;

// A material parameter, stored in SI: value · factor.
Apply material(const char* key, double factor) {
  return [key, factor](double v, simulate::MaterialSpec& m, simulate::ProtocolSettings&) {
    m.params[key] = v * factor;
  };
}

// A protocol setting, in its own (clinical) unit.
Apply protocol(double simulate::ProtocolSettings::*field) {
  return
      [field](double v, simulate::MaterialSpec&, simulate::ProtocolSettings& p) { p.*field = v; };
}

// The straining drive, in kPa: fitting it means the model voids by straining.
void straining(double kpa, simulate::MaterialSpec&, simulate::ProtocolSettings& p) {
  p.drive = simulate::VoidingDrive::Straining;
  p.straining_kpa = kpa;
}

// The urethra's opening pressure; its closing pressure (at most the opening one) follows
// a fitted p_open below it.
void opening_pressure(double cmh2o, simulate::MaterialSpec&, simulate::ProtocolSettings& p) {
  p.p_open_cmh2o = cmh2o;
  p.p_close_cmh2o = std::min(p.p_close_cmh2o, cmh2o);
}

// The urethra's closing pressure; its opening pressure (at least the closing one) follows
// a fitted p_close above it.
void closing_pressure(double cmh2o, simulate::MaterialSpec&, simulate::ProtocolSettings& p) {
  p.p_close_cmh2o = cmh2o;
  p.p_open_cmh2o = std::max(p.p_open_cmh2o, cmh2o);
}

// A fitted bulk modulus no longer follows mu.
void bulk_modulus(double kpa, simulate::MaterialSpec& m, simulate::ProtocolSettings&) {
  m.params.erase("K_per_mu");
  m.params["K"] = units::pa_from_kpa(kpa);
}

using simulate::ProtocolSettings;

// One line a parameter: name, unit, start, lower, upper, voiding only, how it applies.
const std::vector<ModelParameter>& all_parameters() {
  static const std::vector<ModelParameter> all = {
      {{"mu", "kPa", 5.0, 0.1, 100.0, false}, material("mu", 1e3)},
      {{"k", "kPa", 10.0, 0.1, 1e4, false}, bulk_modulus},
      {{"beta", "-", 0.15, 1e-3, 50.0, false}, material("beta", 1.0)},
      {{"tau", "s", 1e-4, 1e-6, 1e3, false}, material("tau", 1.0)},
      {{"k1", "Pa", 10.0, 1e-2, 1e5, false}, material("k1", 1.0)},
      {{"k2", "-", 1.0, 1e-2, 100.0, false}, material("k2", 1.0)},
      {{"p_open", "cmH2O", 20.0, 0.5, 150.0, true}, opening_pressure},
      {{"r1", "cmH2O s/ml", 0.2, 1e-4, 20.0, true}, protocol(&ProtocolSettings::r1_cmh2o_s_per_ml)},
      {{"r2", "cmH2O s2/ml2", 0.02, 1e-5, 5.0, true},
       protocol(&ProtocolSettings::r2_cmh2o_s2_per_ml2)},
      // The detrusor's contractility, the wall material's (docs/physics.md §2.6, §12), up to
      // well beyond the strongest reported isovolumetric pressures (docs/compare.md).
      {{"detrusor", "kPa", 100.0, 0.1, 300.0, true}, material("contractility", 1e3)},
      {{"straining", "kPa", 4.0, 0.1, 20.0, true}, straining},
      // The latency of the drive from the end of filling: the onset of flow (§7.2).
      {{"activation_delay", "s", 5.0, 0.1, 60.0, true},
       protocol(&ProtocolSettings::activation_delay_s)},
      {{"activation_onset", "s", 2.0, 0.05, 60.0, true},
       protocol(&ProtocolSettings::activation_onset_s)},
      // The fade of the drive sets the flow's tail-off and so the flow time (§7.2).
      {{"activation_fade", "s", 5.0, 0.1, 60.0, true},
       protocol(&ProtocolSettings::activation_fade_s)},
      {{"p_close", "cmH2O", 10.0, 0.5, 150.0, true}, closing_pressure},
      // The sphincter's recovery once the urethra is open: the flow's tail and the
      // after-contraction of a detrusor voiding against a closing urethra (physics.md §5).
      {{"urethra_recovery", "-", 0.5, 0.02, 1.0, true},
       protocol(&ProtocolSettings::urethra_recovery_half)},
  };
  return all;
}

ModelRun run_once(const CystometryModel& m) {
  const auto result = simulate::run_cystometry(m.wall, m.material, m.protocol, m.run);
  ModelRun run;
  run.recording = recording_from_history(result.history);
  run.completed = result.completed;
  run.failure = result.failure;
  run.notes = result.notes;
  return run;
}

}  // namespace

std::vector<std::string> model_parameter_names() {
  std::vector<std::string> names;
  for (const auto& p : all_parameters()) names.push_back(p.fit.name);
  return names;
}

ModelParameter model_parameter(const std::string& name) {
  std::string choices;
  for (const auto& p : all_parameters()) {
    if (p.fit.name == name) return p;
    choices += (choices.empty() ? "" : ", ") + p.fit.name;
  }
  usage_error("--calibrate: unknown parameter \"" + name + "\"", "choose from " + choices);
}

Recording recording_from_history(const std::vector<simulate::HistoryRow>& h) {
  Recording r;
  r.source = "calibration run";
  for (const auto& row : h) {
    r.time_s.push_back(row.time_s);
    r.infused_ml.push_back(row.infused_ml);
    r.volume_ml.push_back(row.volume_ml);
    r.pves_cmh2o.push_back(row.pves_cmh2o);
    r.pabd_cmh2o.push_back(row.pabd_cmh2o);
    r.pdet_recorded_cmh2o.push_back(row.pdet_cmh2o);
    r.flow_ml_s.push_back(row.flow_ml_s);
    r.voided_ml.push_back(row.voided_ml);
  }
  return r;
}

ModelSimulator cystometry_simulator(const CystometryModel& base,
                                    const std::vector<ModelParameter>& parameters,
                                    double capacity_ml, bool voiding, bool differentiated) {
  CystometryModel m = base;
  m.protocol.capacity_ml = capacity_ml;
  m.protocol.void_after_fill = voiding;
  m.run.filling_only = !voiding;
  m.run.output_dir.clear();
  m.run.on_progress = nullptr;
  // Every iteration a fresh tangent when the fit differentiates this model: its
  // finite-difference Jacobian needs curves converged far below the Newton tolerance
  // (quadratic convergence overshoots it), not the chord iterations' just-below-tolerance
  // ones, whose noise narrows the intervals. A model the output space mapping only runs
  // keeps the cheaper chord iterations.
  if (differentiated) m.run.newton.reuse_tangent_ratio = 0.0;
  return [m, parameters](const std::vector<double>& values) {
    CystometryModel trial = m;
    for (std::size_t j = 0; j < parameters.size(); ++j)
      parameters[j].apply(values[j], trial.material, trial.protocol);
    ModelRun run = run_once(trial);
    if (run.completed) return run;
    // Retried once with halved steps before it counts as a failed evaluation.
    trial.run.max_fill_step_ml /= 2;
    trial.run.max_void_step_s /= 2;
    trial.run.max_void_step_ml /= 2;
    ModelRun retry = run_once(trial);
    if (!retry.completed) {
      log()->debug("calibration run failed: {}", retry.failure);
      retry.failure += " (also with halved steps)";
    }
    return retry;
  };
}

CystometryModel surrogate_of(const CystometryModel& model) {
  // simulate's level 0: the same wall's sphere-equivalent with the same material,
  // activation and urethra (docs/physics.md §11), milliseconds a cystometry. Its misfit to
  // the wall is what the output space mapping corrects, with a few wall runs in all.
  CystometryModel surrogate = model;
  surrogate.run.level = 0;
  return surrogate;
}

FitOutcome calibrate(const CalibrationProblem& pb) {
  if (pb.targets.size() < 2)
    usage_error("--calibrate: fewer than two measured readings to fit",
                "check --fit-volume-ml against the recording's volumes");
  FitProblem fit;
  for (const auto& p : pb.parameters) fit.parameters.push_back(p.fit);
  fit.targets = pb.targets;
  const double capacity = pb.targets.capacity_ml;
  const bool voiding = pb.targets.voiding;
  // With a surrogate the wall is only run (the Jacobian is the corrected surrogate's).
  fit.model = cystometry_simulator(pb.model, pb.parameters, capacity, voiding, !pb.use_surrogate);
  fit.model_name = "wall of " + std::to_string(pb.model.wall.triangle_count()) + " triangles";
  const double end = std::max(capacity, pb.data_end_ml);
  if (end > capacity)
    fit.final_model = cystometry_simulator(pb.model, pb.parameters, end, voiding, false);
  if (pb.use_surrogate) {
    const CystometryModel surrogate = surrogate_of(pb.model);
    fit.surrogate = cystometry_simulator(surrogate, pb.parameters, capacity, voiding, true);
    fit.surrogate_name = "0-D sphere-equivalent of the wall (surrogate)";
  }
  fit.budget = pb.budget;
  return fit_parameters(fit);
}

}  // namespace vesica::compare
