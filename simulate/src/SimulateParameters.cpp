// vesica-simulate's parameter table (SimulateParameters.h): one entry per option, bound to
// the fields of SimulateSettings, whose initialisers are the defaults; the physical
// parameters' entries from the parameter catalogue, whose defaults the material's are.
#include "vesica/simulate/SimulateParameters.h"

#include <algorithm>

#include "verification/VerificationParameters.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/simulate/ParameterCatalogue.h"
#include "vesica/simulate/SimulateSettings.h"

namespace vesica::simulate {
namespace {

constexpr std::size_t kMaxBranches = 5;  // Maxwell branches a material takes (docs/physics.md §2)
const NumberRange kVolume = NumberRange::greater_than(0).at_most(5000);  // ml

// "a,b,c": up to kMaxBranches numbers, each in `range`.
std::vector<double> list_from_text(const std::string& text, const NumberRange& range,
                                   const std::string& unit) {
  std::vector<double> values = numbers_from_text(text, 0, "a,b,...");
  if (values.size() > kMaxBranches)
    throw ParameterValueError("'" + text + "' has " + std::to_string(values.size()) +
                              " values; at most " + std::to_string(kMaxBranches) +
                              " Maxwell branches");
  for (double v : values)
    if (!range.contains(v)) throw_out_of_range(format_number(v), range, unit);
  return values;
}

void add_list(ParameterTable& t, const std::string& name, std::vector<double>& field,
              const std::string& unit, const NumberRange& range, const std::string& help) {
  t.custom(
      name, unit, "a,b,... (up to 5), each in " + range.describe(unit), help,
      [&field, range, unit](const std::string& text) { field = list_from_text(text, range, unit); },
      [&field] { return nlohmann::json(field); });
}

// An earlier key of a parameter, still accepted: it sets the parameter and says its name.
void add_old_key(ParameterTable& t, const PhysicalParameter& p, Parameter& current) {
  Parameter* target = &current;  // the table's entries keep their address (a deque)
  const std::string old_key = p.old_key, key = p.key;
  t.custom(
      old_key, p.unit, "as " + key, "the earlier name of " + key + ": give " + key,
      [target, old_key, key](const std::string& text) {
        vesica::log()->warn("{} is the earlier name of {}: give {}", old_key, key, key);
        target->assign(text);
      },
      [] { return nlohmann::json(); });
}

// The materials a parameter applies to, for its help: " (bladder, neobladder, fibers)",
// nothing when it applies to all.
std::string applies_text(const PhysicalParameter& p) {
  std::string names;
  std::size_t count = 0;
  for (const NamedMaterial& m : named_materials())
    if (p.applies_to(m.name)) names += (count++ ? ", " : "") + m.name;
  return count < named_materials().size() ? " (" + names + ")" : "";
}

// "--contractility-kpa" of "contractility_kpa".
std::string option_of(const std::string& key) {
  std::string option = "--" + key;
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

}  // namespace

void add_material_entries(MaterialChoice& m, ParameterTable& t) {
  std::vector<std::string> names;
  for (const NamedMaterial& n : named_materials()) names.push_back(n.name);
  t.choice("material", m.name, names,
           "wall material (docs/physics.md §2): the normal adult detrusor, an ileal neobladder, "
           "or a plain law");
  for (const PhysicalParameter& p : parameter_catalogue()) {
    if (!p.is_material()) continue;
    const std::string help = p.help + (p.per_branch ? "" : applies_text(p));
    if (p.per_branch) {
      add_list(t, p.key, m.branches[p.name], p.unit, p.range, help);
      continue;
    }
    double& field = m.values.emplace(p.name, kMaterialDefault).first->second;
    Parameter& entry = t.number_or_word(
        p.key, field, kMaterialDefault, p.unit,
        NumberRange(p.range).or_word("auto", "the material's own (docs/parameters.md)"), help);
    if (!p.old_key.empty()) add_old_key(t, p, entry);
  }
}

void add_drive_entries(ProtocolSettings& protocol, ParameterTable& t) {
  t.choice<VoidingDrive>(
      "drive", protocol.drive,
      {{"detrusor", VoidingDrive::Detrusor}, {"straining", VoidingDrive::Straining}},
      "what voids the bladder: the detrusor's contraction or abdominal straining");
  for (const PhysicalParameter& p : parameter_catalogue())
    if (!p.is_material()) t.number(p.key, protocol.*(p.field), p.unit, p.range, p.help);
}

void add_wall_reference_entries(WallOptions& w, ParameterTable& t) {
  t.number("thickness_mm", w.thickness_mm, "mm", NumberRange::at_least(0.1).at_most(30),
           "wall thickness where the mesh gives none");
  t.number("residual_ml", w.residual_ml, "ml", NumberRange::at_least(1).at_most(5000),
           "stress-free (residual) volume of the scaled reference");
  t.number("residual_fraction", w.residual_fraction, "-",
           NumberRange::greater_than(0).at_most(1).or_value(0, "use residual_ml"),
           "stress-free volume as a fraction of the mesh's (a neobladder's retracted tissue)");
}

void add_start_entry(ProtocolSettings& p, ParameterTable& t) {
  t.number("start_ml", p.start_ml, "ml", kVolume, "volume at the start of filling");
}

void add_model_entries(SimulateSettings& s, ParameterTable& t) {
  add_material_entries(s.material, t);
  add_wall_reference_entries(s.wall, t);
  add_start_entry(s.protocol, t);
  add_drive_entries(s.protocol, t);
}

MaterialSpec material_spec(const MaterialChoice& m) {
  MaterialSpec spec{m.name, {}};
  for (const PhysicalParameter& p : parameter_catalogue()) {
    if (!p.is_material() || !m.given(p.name)) continue;
    if (!p.applies_to(m.name))
      usage_error(option_of(p.key) + " does not apply to material " + m.name,
                  "it applies to" + applies_text(p));
    if (!p.per_branch) spec.params[p.material_key] = m.values.at(p.name) * p.si_per_unit;
  }
  const auto list = [&m](const char* name) {
    const auto it = m.branches.find(name);
    return it == m.branches.end() ? std::vector<double>() : it->second;
  };
  const std::vector<double> beta = list("beta"), tau = list("tau");
  if (beta.size() != tau.size()) usage_error("--beta and --tau-s need the same number of values");
  for (std::size_t a = 0; a < beta.size(); ++a) {
    spec.params["beta" + std::to_string(a + 1)] = beta[a];
    spec.params["tau" + std::to_string(a + 1)] = tau[a];
  }
  return spec;
}

namespace {

void add_wall_entries(SimulateSettings& s, ParameterTable& t) {
  WallOptions& w = s.wall;
  ProtocolSettings& p = s.protocol;
  add_wall_reference_entries(w, t);
  t.choice<ReferenceState>(
      "reference", w.reference,
      {{"scale", ReferenceState::Scale}, {"prestress", ReferenceState::Prestress}},
      "stress-free reference: the image scaled to residual_ml, or the "
      "image prestressed at image_pressure_cmh2o");
  t.number("image_pressure_cmh2o", p.image_pressure_cmh2o, "cmH2O",
           NumberRange::at_least(0).at_most(200),
           "pressure of the imaged bladder (reference prestress)");
  t.choice<Posture>("posture", s.posture,
                    {{"supine", Posture::Supine}, {"sitting", Posture::Sitting}},
                    "gravity direction in LPS: supine posterior, sitting inferior");
  t.flag_off("no_gravity", p.gravity, "no hydrostatic pressure and no wall weight");
  t.number("urine_density_kg_m3", p.urine_density, "kg/m3",
           NumberRange::at_least(900).at_most(1200), "density of the urine");
  t.number("abdominal_density_kg_m3", p.abdominal_density, "kg/m3",
           NumberRange::at_least(0).at_most(1200),
           "density of the abdominal contents around the wall (0: a bladder in air)");
  t.flag("wall_weight", p.wall_weight, "load the wall with its own weight");
  t.number("wall_density_kg_m3", p.wall_density, "kg/m3", NumberRange::at_least(800).at_most(1500),
           "density of the wall (weight and inertia)");
  t.number("support_kpa_per_mm", p.support_kpa_per_mm, "kPa/mm",
           NumberRange::at_least(0).at_most(1000), "spring stiffness of the support region");
  t.number("wall_drag_pa_s_per_m", p.wall_drag_pa_s_per_m, "Pa*s/m",
           NumberRange::at_least(0).at_most(1e9),
           "viscous drag of the surrounding tissue on the wall");
  t.flag_off("no_wrinkling", p.wrinkling,
             "let the wall carry compression instead of wrinkling (tension field)");
  t.number("wrinkle_regularisation", p.wrinkle_regularisation, "-",
           NumberRange::at_least(0).at_most(ProtocolSettings::kMaxWrinkleRegularisation),
           "share of the plain law's stress a wrinkled or slack element keeps (the compression "
           "a wall of finite thickness carries before it buckles; 0: the pure tension field)");
}

void add_protocol_entries(ProtocolSettings& p, ParameterTable& t) {
  add_start_entry(p, t);
  t.number("capacity_ml", p.capacity_ml, "ml", kVolume, "cystometric capacity (end of filling)");
  t.number("fill_limit_cmh2o", p.fill_limit_cmh2o, "cmH2O",
           NumberRange::greater_than(0).at_most(200).or_value(0, "fill to capacity_ml"),
           "filling also ends when Pdet reaches this (a study's pressure limit)");
  t.number("fill_rate_ml_min", p.fill_rate_ml_min, "ml/min",
           NumberRange::at_least(1).at_most(1000).because(
               "at 0 filling never ends; cystometry fills at 10-100 ml/min"),
           "infusion rate");
  t.number("hold_s", p.hold_s, "s",
           NumberRange::at_least(0).at_most(3600).because(
               "an hour of hold is beyond any cystometry (and writes a frame every 10 s)"),
           "hold at capacity before voiding");
  t.number("pabd_cmh2o", p.pabd_cmh2o, "cmH2O", NumberRange::at_least(-20).at_most(200),
           "resting abdominal pressure");
  t.flag_off("no_void", p.void_after_fill, "stop after filling (and hold)");
  add_drive_entries(p, t);
  t.number("stop_flow_ml_s", p.stop_flow_ml_s, "ml/s", NumberRange::greater_than(0).at_most(50),
           "voiding ends when the flow falls below this");
  t.number("max_void_s", p.max_void_s, "s", NumberRange::greater_than(0).at_most(3600),
           "longest voiding phase");
}

void add_run_entries(RunOptions& r, ParameterTable& t) {
  t.flag("dynamic", r.dynamic, "Bossak-Newmark wall inertia instead of quasi-static steps");
  t.number("bossak_alpha", r.bossak_alpha, "-", NumberRange::at_least(-1.0 / 3.0).at_most(0),
           "Bossak alpha (0: no numerical damping)");
  t.flag("hand_over", r.hand_over,
         "a voiding step the running level cannot take hands the rest of voiding to the level "
         "below (the fallback: level 2 to 1, 1 to its sphere-equivalent) instead of ending it "
         "there");
  t.integer("level", r.level, "-", NumberRange::at_least(0).at_most(2),
            "0: lumped sphere-equivalent bladder (milliseconds); 1: urine as a hydrostatic "
            "volume (seconds); 2: Navier-Stokes urine on the tetrahedra of vesica-mesh "
            "--fluid (velocity, wall shear; minutes)");
  t.integer("newton_krylov_solves", r.newton.preconditioned_reuse.max_iterations, "-",
            NumberRange::at_least(0).at_most(50),
            "level 1: GMRES solves per Newton increment on a reused factorization before a new "
            "one (0: a factorization every increment)");
  t.number("fluid_dt_s", r.level2.fill_dt_s, "s",
           NumberRange::at_least(1e-3).at_most(60).or_value(
               0, "adaptive: growing after easy steps up to max_fill_step_ml"),
           "level 2: time step while filling");
  t.number("void_dt_s", r.level2.void_dt_s, "s",
           NumberRange::at_least(1e-3).at_most(1).or_value(
               0, "adaptive: from the flow's and volume's change and the Newton iterations"),
           "level 2: time step while voiding");
  t.number("void_dt_min_s", r.level2.void_dt_min_s, "s", NumberRange::at_least(1e-4).at_most(1),
           "level 2: shortest adaptive voiding step (at the urethra's opening)");
  t.number("void_dt_max_s", r.level2.void_dt_max_s, "s", NumberRange::at_least(1e-4).at_most(10),
           "level 2: longest adaptive voiding step (plateau and tail of the flow)");
  t.number("urine_viscosity_pa_s", r.level2.urine_viscosity, "Pa*s",
           NumberRange::at_least(1e-4).at_most(1), "level 2: urine viscosity");
  t.choice<Level2LinearSolver>(
      "linear_solver", r.level2.linear_solver,
      {{"krylov", Level2LinearSolver::Krylov}, {"direct", Level2LinearSolver::Direct}},
      "level 2: krylov (GMRES on a reused LU) or direct (an LU every Newton iteration)");
  t.flag_off("no_series", r.write_series, "do not write the .pvd/.vtu series");
  t.number("checkpoint_minutes", r.checkpoints.interval_min, "min",
           NumberRange::greater_than(0).at_most(1440),
           "compute time between two checkpoints of a level-1 or level-2 run, which --resume "
           "continues from (docs/simulate.md)");
}

}  // namespace

ParameterTable parameter_table(SimulateSettings& s) {
  ParameterTable t("simulate");
  add_material_entries(s.material, t);
  add_wall_entries(s, t);
  add_protocol_entries(s.protocol, t);
  add_run_entries(s.run, t);
  add_verification_entries(s, t);
  return t;
}

ParameterTable parameter_table() {
  return table_with_defaults<SimulateSettings>(parameter_table);
}

}  // namespace vesica::simulate
