// vesica-simulate's parameter table (SimulateParameters.h): one entry per option, bound to
// the fields of SimulateSettings, whose initialisers are the defaults.
#include "vesica/simulate/SimulateParameters.h"

#include "verification/VerificationParameters.h"
#include "vesica/simulate/SimulateSettings.h"

namespace vesica::simulate {
namespace {

constexpr std::size_t kMaxBranches = 5;  // Maxwell branches a material takes (docs/physics.md §2)

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

// A material parameter in `range`, or "auto" for the named material's own value.
void add_material_number(ParameterTable& t, const std::string& name, double& field,
                         const std::string& unit, NumberRange range, const std::string& help) {
  t.number_or_word(name, field, kMaterialDefault, unit,
                   range.or_word("auto", "the material's own (docs/simulate.md)"), help);
}

void add_material_entries(SimulateSettings& s, ParameterTable& t) {
  t.choice("material", s.material, {"bladder", "neobladder", "neo-hookean", "maxwell", "fibers"},
           "wall material (docs/physics.md §2): the normal adult detrusor, an ileal neobladder, "
           "or a plain law");
  add_material_number(
      t, "mu_kpa", s.mu_kpa, "kPa",
      NumberRange::at_least(0.1).at_most(100).because(
          "the calibration's range; a stiffer wall barely moves under cystometric pressures"),
      "shear modulus mu of the matrix");
  add_material_number(t, "k_kpa", s.k_kpa, "kPa", NumberRange::at_least(0.1).at_most(1e6),
                      "bulk modulus K (material default 1000 mu, nearly incompressible; the "
                      "thesis's 10 kPa dilates and peaks near 1.5x the residual volume)");
  add_material_number(t, "k1_kpa", s.k1_kpa, "kPa", NumberRange::greater_than(0).at_most(1000),
                      "fiber stiffness k1 (bladder, neobladder, fibers)");
  add_material_number(t, "k2", s.k2, "-", NumberRange::greater_than(0).at_most(100),
                      "fiber exponent k2 (bladder, neobladder, fibers)");
  add_list(t, "beta", s.beta, "-", NumberRange::at_least(0).at_most(50),
           "Maxwell branch strengths (none: the material's branches)");
  add_list(t, "tau_s", s.tau_s, "s", NumberRange::at_least(1e-6).at_most(1000),
           "Maxwell relaxation times, one per beta");
  add_material_number(t, "tone_kpa", s.tone_kpa, "kPa", NumberRange::at_least(0).at_most(100),
                      "detrusor tone: nominal active fiber stress at rest");
  add_material_number(t, "detrusor_kpa", s.detrusor_kpa, "kPa",
                      NumberRange::at_least(0).at_most(1000),
                      "detrusor contractility: nominal active fiber stress added at full "
                      "activation and optimal length");
  add_material_number(t, "optimal_stretch", s.optimal_stretch, "-",
                      NumberRange::at_least(0.5).at_most(5),
                      "fiber stretch (from the reference) of the detrusor's greatest force");
  add_material_number(t, "stretch_width", s.stretch_width, "-",
                      NumberRange::at_least(0.1).at_most(5),
                      "width of the detrusor's length-tension curve");
  add_material_number(t, "hill_a", s.hill_a, "-", NumberRange::at_least(0.05).at_most(5),
                      "Hill's a/T0: curvature of the detrusor's force-velocity relation");
  add_material_number(t, "hill_vmax_per_s", s.hill_vmax_per_s, "1/s",
                      NumberRange::at_least(1e-3).at_most(10),
                      "the detrusor's unloaded shortening rate");
}

void add_wall_entries(SimulateSettings& s, ParameterTable& t) {
  WallOptions& w = s.wall;
  ProtocolSettings& p = s.protocol;
  t.number("thickness_mm", w.thickness_mm, "mm", NumberRange::at_least(0.1).at_most(30),
           "wall thickness where the mesh gives none");
  t.choice<ReferenceState>(
      "reference", w.reference,
      {{"scale", ReferenceState::Scale}, {"prestress", ReferenceState::Prestress}},
      "stress-free reference: the image scaled to residual_ml, or the "
      "image prestressed at image_pressure_cmh2o");
  t.number("residual_ml", w.residual_ml, "ml", NumberRange::at_least(1).at_most(5000),
           "stress-free (residual) volume of the scaled reference");
  t.number("residual_fraction", w.residual_fraction, "-",
           NumberRange::greater_than(0).at_most(1).or_value(0, "use residual_ml"),
           "stress-free volume as a fraction of the mesh's (a neobladder's retracted tissue)");
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
}

void add_protocol_entries(ProtocolSettings& p, ParameterTable& t) {
  const NumberRange volume = NumberRange::greater_than(0).at_most(5000);
  t.number("start_ml", p.start_ml, "ml", volume, "volume at the start of filling");
  t.number("capacity_ml", p.capacity_ml, "ml", volume, "cystometric capacity (end of filling)");
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
  t.number("p_open_cmh2o", p.p_open_cmh2o, "cmH2O", NumberRange::at_least(0).at_most(300),
           "urethral opening pressure (Pves)");
  t.number("p_close_cmh2o", p.p_close_cmh2o, "cmH2O", NumberRange::at_least(0).at_most(300),
           "urethral closing pressure (Pves), at most p_open_cmh2o");
  t.number("urethra_half_open_cmh2o", p.urethra_half_open_cmh2o, "cmH2O",
           NumberRange::at_least(0).at_most(100),
           "collapsible urethra: pressure above closing at which its lumen is about half "
           "open (0: rigid, the quadratic law)");
  t.number("urethra_recovery_half", p.urethra_recovery_half, "-",
           NumberRange::greater_than(0).at_most(1),
           "the sphincter's recovery: the voided fraction at which the urethra's closing "
           "pressure has risen half-way back to p_open_cmh2o (0.5: linearly; 1: no recovery)");
  t.number("r1", p.r1_cmh2o_s_per_ml, "cmH2O*s/ml", NumberRange::at_least(0).at_most(100),
           "urethral linear resistance R1");
  t.number("r2", p.r2_cmh2o_s2_per_ml2, "cmH2O*s2/ml2", NumberRange::at_least(0).at_most(100),
           "urethral quadratic resistance R2");
  t.choice<VoidingDrive>(
      "drive", p.drive,
      {{"detrusor", VoidingDrive::Detrusor}, {"straining", VoidingDrive::Straining}},
      "what voids the bladder: the detrusor's contraction or abdominal straining");
  t.number("straining_kpa", p.straining_kpa, "kPa", NumberRange::at_least(0).at_most(50),
           "abdominal straining pressure at full activation (drive straining)");
  t.number("activation_delay_s", p.activation_delay_s, "s", NumberRange::at_least(0).at_most(120),
           "latency from the end of filling to the drive's activation (0: at once)");
  t.number("activation_onset_s", p.activation_onset_s, "s", NumberRange::at_least(0).at_most(60),
           "time constant of the drive's activation (0: at once)");
  t.number("activation_plateau_s", p.activation_plateau_s, "s",
           NumberRange::at_least(0).at_most(3600),
           "how long the drive stays activated from the start of voiding");
  t.number("activation_fade_s", p.activation_fade_s, "s", NumberRange::at_least(0).at_most(60),
           "time constant of the drive's relaxation after the plateau (0: at once)");
  t.number("stop_flow_ml_s", p.stop_flow_ml_s, "ml/s", NumberRange::greater_than(0).at_most(50),
           "voiding ends when the flow falls below this");
  t.number("max_void_s", p.max_void_s, "s", NumberRange::greater_than(0).at_most(3600),
           "longest voiding phase");
}

void add_run_entries(RunOptions& r, ParameterTable& t) {
  t.flag("dynamic", r.dynamic, "Bossak-Newmark wall inertia instead of quasi-static steps");
  t.number("bossak_alpha", r.bossak_alpha, "-", NumberRange::at_least(-1.0 / 3.0).at_most(0),
           "Bossak alpha (0: no numerical damping)");
  t.integer("level", r.level, "-", NumberRange::at_least(0).at_most(2),
            "0: lumped sphere-equivalent bladder (milliseconds); 1: urine as a hydrostatic "
            "volume (seconds); 2: Navier-Stokes urine on the tetrahedra of vesica-mesh "
            "--fluid (velocity, wall shear; minutes)");
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
  add_material_entries(s, t);
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
