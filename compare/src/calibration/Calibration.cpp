#include "vesica/compare/calibration/Calibration.h"

#include <algorithm>
#include <cmath>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/ParameterCatalogue.h"

namespace vesica::compare {
namespace {

using Apply = std::function<void(double, simulate::MaterialSpec&, simulate::ProtocolSettings&)>;

// A material parameter, in the catalogue's unit, stored in SI under its material key; a
// Maxwell branch's strength or time is the first branch's (the others keep theirs).
Apply material(const simulate::PhysicalParameter& p) {
  const std::string key = p.per_branch ? p.material_key + "1" : p.material_key;
  const double si_per_unit = p.si_per_unit;
  return [key, si_per_unit, bare = p.material_key](double v, simulate::MaterialSpec& m,
                                                   simulate::ProtocolSettings&) {
    m.params.erase(bare);  // "beta"/"tau" spell the first branch too
    m.params[key] = v * si_per_unit;
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

// How a catalogue parameter's value enters the model: most by their key or field alone;
// the straining (which sets the drive), the urethra's pair (which keeps p_close <= p_open)
// and the bulk modulus (which stops following mu) do more.
Apply applier(const simulate::PhysicalParameter& p) {
  if (p.name == "straining") return straining;
  if (p.name == "p_open") return opening_pressure;
  if (p.name == "p_close") return closing_pressure;
  if (p.name == "k") return bulk_modulus;
  return p.is_material() ? material(p) : protocol(p.field);
}

// Every parameter of the catalogue a calibration fits (ParameterCatalogue.h): its name,
// unit, search range and phase; its start is the model's (CalibrationRun.cpp).
const std::vector<ModelParameter>& all_parameters() {
  static const std::vector<ModelParameter> all = [] {
    std::vector<ModelParameter> list;
    for (const simulate::PhysicalParameter& p : simulate::parameter_catalogue()) {
      if (!p.fitted()) continue;
      const FitParameter fit{
          p.name, p.unit, p.fit_range->lower, p.fit_range->lower, p.fit_range->upper, p.voiding};
      list.push_back({fit, applier(p)});
    }
    return list;
  }();
  return all;
}

ModelRun run_once(const CystometryModel& m) {
  const auto result = simulate::run_cystometry(m.wall, m.material, m.protocol, m.run);
  ModelRun run;
  run.recording = recording_from_history(result.history);
  run.completed = result.completed;
  run.failure = result.failure;
  run.notes = result.notes;
  run.card = result.card;
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
  const simulate::PhysicalParameter* entry = simulate::find_parameter(name);
  for (const auto& p : all_parameters()) {
    if (entry && (name == entry->name || name == entry->old_name) && p.fit.name == entry->name) {
      if (name != entry->name)
        log()->warn("--calibrate: {} is the earlier name of {}: give {}", name, entry->name,
                    entry->name);
      return p;
    }
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
