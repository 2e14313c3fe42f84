// The parameter catalogue (ParameterCatalogue.h): one entry per physical parameter. The
// defaults of the named materials are docs/simulate.md's "Default walls" (bladder:
// fitted to the shared normal recording on the CT bladder and from the literature cited
// there; neobladder: a soft, slowly stiffening ileal wall that holds a reservoir at a few
// cmH2O when stress-free at its retracted size, from the neobladder literature cited
// there); the plain laws keep the thesis's values (docs/physics.md §2.7).
#include "vesica/simulate/ParameterCatalogue.h"

#include <algorithm>

#include "vesica/core/Error.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {

using Defaults = std::vector<std::pair<std::string, std::vector<double>>>;

// One value for every named material.
Defaults everywhere(double si) {
  Defaults d;
  for (const NamedMaterial& m : named_materials()) d.push_back({m.name, {si}});
  return d;
}

// The bladder's own value, the others' shared one (the muscle's curve of an inactive
// muscle: it only acts once a contractility or tone is given).
Defaults bladder_or(double bladder, double others) {
  Defaults d = everywhere(others);
  for (auto& [name, values] : d)
    if (name == "bladder") values = {bladder};
  return d;
}

PhysicalParameter material(std::string name, std::string key, std::string unit, std::string si_unit,
                           double si_per_unit, NumberRange range, Defaults defaults,
                           std::string help) {
  PhysicalParameter p;
  p.material_key = name;
  p.name = std::move(name);
  p.key = std::move(key);
  p.unit = std::move(unit);
  p.si_unit = std::move(si_unit);
  p.si_per_unit = si_per_unit;
  p.range = std::move(range);
  p.defaults = std::move(defaults);
  p.help = std::move(help);
  return p;
}

PhysicalParameter protocol(std::string name, std::string key, std::string unit, std::string si_unit,
                           double si_per_unit, NumberRange range, double ProtocolSettings::*field,
                           std::string help) {
  PhysicalParameter p;
  p.name = std::move(name);
  p.key = std::move(key);
  p.unit = std::move(unit);
  p.si_unit = std::move(si_unit);
  p.si_per_unit = si_per_unit;
  p.range = std::move(range);
  p.field = field;
  p.help = std::move(help);
  p.voiding = true;
  return p;
}

PhysicalParameter fitted(PhysicalParameter p, double lower, double upper, std::string why = "") {
  p.fit_range = FitRange{lower, upper, std::move(why)};
  return p;
}

constexpr double kPa = 1e3;  // Pa per kPa
const double kCmH2O = units::kPaPerCmH2O;
// cmH2O·s/ml and cmH2O·s²/ml² in Pa·s/m³ and Pa·s²/m⁶
const double kR1 = units::kPaPerCmH2O / units::kM3PerMl;
const double kR2 = units::kPaPerCmH2O / (units::kM3PerMl * units::kM3PerMl);

std::vector<PhysicalParameter> wall_parameters() {
  std::vector<PhysicalParameter> w;
  w.push_back(
      fitted(material("mu", "mu_kpa", "kPa", "Pa", kPa,
                      NumberRange::at_least(0.1).at_most(100).because(
                          "the calibration's range; a stiffer wall barely moves under cystometric "
                          "pressures"),
                      {{"bladder", {0.6e3}},
                       {"neobladder", {2e3}},
                       {"neo-hookean", {5e3}},
                       {"maxwell", {5e3}},
                       {"fibers", {5e3}}},
                      "shear modulus mu of the matrix"),
             0.1, 100.0));
  PhysicalParameter k = material(
      "k", "k_kpa", "kPa", "Pa", kPa, NumberRange::at_least(0.1).at_most(1e6), {},
      "bulk modulus K (default 1000 mu, nearly incompressible: the wall is mostly water; the "
      "thesis's 10 kPa dilates and peaks near 1.5x the residual volume)");
  k.material_key = "K";
  k.default_per_mu = 1e3;
  w.push_back(fitted(k, 0.1, 1e4,
                     "beyond 10 MPa (10,000 mu of the softest wall) the wall is "
                     "incompressible for every filling: K no longer changes Pdet"));
  w.push_back(
      fitted(material("k1", "k1_kpa", "kPa", "Pa", kPa, NumberRange::greater_than(0).at_most(1000),
                      {{"bladder", {125.0}}, {"neobladder", {200.0}}, {"fibers", {10e3}}},
                      "fiber stiffness k1"),
             1e-5, 100.0,
             "from a fiber that never stiffens within a cystometry (10 mPa) to one that holds any "
             "bladder near its start volume (100 kPa)"));
  w.push_back(fitted(material("k2", "k2", "-", "-", 1.0, NumberRange::greater_than(0).at_most(100),
                              {{"bladder", {0.02}}, {"neobladder", {0.045}}, {"fibers", {1.0}}},
                              "fiber exponent k2"),
                     1e-2, 100.0,
                     "below 0.01 the fiber term is linear in I4 over any cystometry and k2 "
                     "is not identified apart from k1"));
  PhysicalParameter beta =
      material("beta", "beta", "-", "-", 1.0, NumberRange::at_least(0).at_most(50),
               {{"bladder", {0.2}}, {"neobladder", {0.2}}, {"maxwell", {0.15}}, {"fibers", {}}},
               "Maxwell branch strengths (none: the material's branches)");
  beta.per_branch = true;
  w.push_back(fitted(beta, 1e-3, 50.0,
                     "a branch weaker than 0.001 of the elastic stress is not seen in a "
                     "recording; the fit moves the first branch"));
  PhysicalParameter tau =
      material("tau", "tau_s", "s", "s", 1.0, NumberRange::at_least(1e-6).at_most(1000),
               {{"bladder", {10.0}}, {"neobladder", {10.0}}, {"maxwell", {1e-4}}, {"fibers", {}}},
               "Maxwell relaxation times, one per beta");
  tau.per_branch = true;
  w.push_back(fitted(tau, 1e-6, 1e3));
  w.push_back(material("beta_vol", "beta_vol", "-", "-", 1.0, NumberRange::at_least(0).at_most(50),
                       everywhere(9.0),
                       "Ogden volumetric exponent beta (docs/physics.md §2.3); 0 = K/2 "
                       "(ln J)^2, FEBio's volumetric law"));
  return w;
}

std::vector<PhysicalParameter> muscle_parameters() {
  std::vector<PhysicalParameter> m;
  m.push_back(material("tone", "tone_kpa", "kPa", "Pa", kPa, NumberRange::at_least(0).at_most(100),
                       everywhere(0.0), "detrusor tone: nominal active fiber stress at rest"));
  PhysicalParameter contractility =
      material("contractility", "contractility_kpa", "kPa", "Pa", kPa,
               NumberRange::at_least(0).at_most(1000), bladder_or(100e3, 0.0),
               "detrusor contractility: nominal active fiber stress added at full activation and "
               "optimal length (0: voided by straining only)");
  contractility.old_key = "detrusor_kpa";
  contractility.old_name = "detrusor";
  contractility.voiding = true;
  m.push_back(fitted(contractility, 0.1, 300.0,
                     "300 kPa gives an isovolumetric Pdet near 170 cmH2O on the CT wall, "
                     "beyond the highest reported, so that a fit cannot trade an absurd "
                     "contractility against a slow onset"));
  m.push_back(material("optimal_stretch", "optimal_stretch", "-", "-", 1.0,
                       NumberRange::at_least(0.5).at_most(5), bladder_or(3.0, 2.0),
                       "fiber stretch (from the reference) of the detrusor's greatest force"));
  m.push_back(material("stretch_width", "stretch_width", "-", "-", 1.0,
                       NumberRange::at_least(0.1).at_most(5), bladder_or(1.5, 1.0),
                       "width of the detrusor's length-tension curve"));
  m.push_back(material("hill_a", "hill_a", "-", "-", 1.0, NumberRange::at_least(0.05).at_most(5),
                       bladder_or(0.3, 0.25),
                       "Hill's a/T0: curvature of the detrusor's force-velocity relation"));
  PhysicalParameter vmax = material("hill_vmax", "hill_vmax_per_s", "1/s", "1/s", 1.0,
                                    NumberRange::at_least(1e-3).at_most(10),
                                    bladder_or(0.25, 0.1), "the detrusor's unloaded shortening rate");
  vmax.voiding = true;  // it sets how long the flow holds as the bladder empties
  m.push_back(fitted(vmax, 0.02, 1.0,
                     "from a detrusor that needs a minute to shorten by its own length to one "
                     "nearly three times the fastest fibres measured (0.37 lengths/s)"));
  return m;
}

std::vector<PhysicalParameter> urethra_and_drive_parameters() {
  using P = ProtocolSettings;
  std::vector<PhysicalParameter> u;
  u.push_back(fitted(protocol("p_open", "p_open_cmh2o", "cmH2O", "Pa", kCmH2O,
                              NumberRange::at_least(0).at_most(300), &P::p_open_cmh2o,
                              "urethral opening pressure (Pves)"),
                     0.5, 150.0, "the urethra opens within the pressures a detrusor makes"));
  u.push_back(fitted(protocol("p_close", "p_close_cmh2o", "cmH2O", "Pa", kCmH2O,
                              NumberRange::at_least(0).at_most(300), &P::p_close_cmh2o,
                              "urethral closing pressure (Pves), at most p_open_cmh2o"),
                     0.5, 150.0, "as p_open"));
  u.push_back(fitted(
      protocol("r1", "r1", "cmH2O*s/ml", "Pa*s/m3", kR1, NumberRange::at_least(0).at_most(100),
               &P::r1_cmh2o_s_per_ml, "urethral linear resistance R1"),
      1e-4, 20.0, "from no resistance at all to one that lets no measurable flow pass"));
  u.push_back(fitted(
      protocol("r2", "r2", "cmH2O*s2/ml2", "Pa*s2/m6", kR2, NumberRange::at_least(0).at_most(100),
               &P::r2_cmh2o_s2_per_ml2, "urethral quadratic resistance R2"),
      1e-5, 5.0, "as r1"));
  u.push_back(protocol("urethra_half_open", "urethra_half_open_cmh2o", "cmH2O", "Pa", kCmH2O,
                       NumberRange::at_least(0).at_most(100), &P::urethra_half_open_cmh2o,
                       "collapsible urethra: pressure above closing at which its lumen is about "
                       "half open (0: rigid, the quadratic law)"));
  PhysicalParameter recovery = protocol(
      "urethra_recovery_half", "urethra_recovery_half", "-", "-", 1.0,
      NumberRange::greater_than(0).at_most(1), &P::urethra_recovery_half,
      "the sphincter's recovery: the voided fraction at which the urethra's closing pressure "
      "has risen half-way back to p_open_cmh2o (0.5: linearly; 1: no recovery)");
  recovery.old_name = "urethra_recovery";
  recovery.fit_start = 0.5;  // the model's 1 (no recovery) is the search's bound
  u.push_back(fitted(recovery, 0.02, 1.0, "below 0.02 the urethra closes at once after opening"));
  u.push_back(fitted(protocol("straining", "straining_kpa", "kPa", "Pa", kPa,
                              NumberRange::at_least(0).at_most(50), &P::straining_kpa,
                              "abdominal straining pressure at full activation (drive straining)"),
                     0.1, 20.0,
                     "20 kPa (204 cmH2O) is beyond any abdominal pressure a patient makes"));
  PhysicalParameter delay =
      protocol("activation_delay", "activation_delay_s", "s", "s", 1.0,
               NumberRange::at_least(0).at_most(120), &P::activation_delay_s,
               "latency from the end of filling to the drive's activation (0: at once)");
  delay.fit_start = 5.0;  // the model's 0 lies outside the search
  u.push_back(
      fitted(delay, 0.1, 60.0, "the onset of flow lies within a minute of the end of filling"));
  u.push_back(fitted(protocol("activation_onset", "activation_onset_s", "s", "s", 1.0,
                              NumberRange::at_least(0).at_most(60), &P::activation_onset_s,
                              "time constant of the drive's activation (0: at once)"),
                     0.05, 60.0));
  u.push_back(protocol("activation_plateau", "activation_plateau_s", "s", "s", 1.0,
                       NumberRange::at_least(0).at_most(3600), &P::activation_plateau_s,
                       "how long the drive stays activated from the start of voiding"));
  u.push_back(fitted(protocol("activation_fade", "activation_fade_s", "s", "s", 1.0,
                              NumberRange::at_least(0).at_most(60), &P::activation_fade_s,
                              "time constant of the drive's relaxation after the plateau (0: at "
                              "once)"),
                     0.1, 60.0, "the fade sets the flow's tail-off and so the flow time"));
  return u;
}

std::vector<PhysicalParameter> build_catalogue() {
  std::vector<PhysicalParameter> all = wall_parameters();
  for (auto* part : {muscle_parameters, urethra_and_drive_parameters})
    for (PhysicalParameter& p : part()) all.push_back(std::move(p));
  return all;
}

}  // namespace

const std::vector<NamedMaterial>& named_materials() {
  static const std::vector<NamedMaterial> materials = {
      {"bladder", "the normal adult detrusor: fibers, one Maxwell branch and a muscle", true},
      {"neobladder", "an ileal neobladder: a soft fiber wall without coordinated contraction",
       true},
      {"neo-hookean", "the thesis's elastic matrix alone", false},
      {"maxwell", "the matrix with the thesis's Maxwell branch", false},
      {"fibers", "the matrix with two fiber families, no branch", true},
  };
  return materials;
}

const NamedMaterial* find_named_material(const std::string& name) {
  for (const NamedMaterial& m : named_materials())
    if (m.name == name) return &m;
  return nullptr;
}

bool PhysicalParameter::applies_to(const std::string& material) const {
  if (!is_material()) return true;
  if (default_per_mu > 0.0) return find_named_material(material) != nullptr;
  return std::any_of(defaults.begin(), defaults.end(),
                     [&](const auto& d) { return d.first == material; });
}

std::vector<double> PhysicalParameter::default_si(const std::string& material, double mu_pa) const {
  if (default_per_mu > 0.0) return {default_per_mu * mu_pa};
  for (const auto& [name, values] : defaults)
    if (name == material) return values;
  usage_error("material '" + material + "' has no parameter " + name);
}

double PhysicalParameter::protocol_default() const {
  return ProtocolSettings{}.*field;
}

const std::vector<PhysicalParameter>& parameter_catalogue() {
  static const std::vector<PhysicalParameter> all = build_catalogue();
  return all;
}

const PhysicalParameter* find_parameter(const std::string& n) {
  for (const PhysicalParameter& p : parameter_catalogue())
    if (n == p.name || n == p.key || (!p.old_key.empty() && n == p.old_key) ||
        (!p.old_name.empty() && n == p.old_name))
      return &p;
  return nullptr;
}

const PhysicalParameter& catalogue_parameter(const std::string& name) {
  std::string choices;
  for (const PhysicalParameter& p : parameter_catalogue()) {
    if (name == p.name || (!p.old_name.empty() && name == p.old_name)) return p;
    choices += (choices.empty() ? "" : ", ") + p.name;
  }
  usage_error("no parameter named \"" + name + "\"", "choose from " + choices);
}

std::vector<double> card_value_si(const ModelCard& card, const PhysicalParameter& p) {
  if (!p.is_material()) return {card.protocol.*(p.field) * p.si_per_unit};
  const MaterialCard& m = card.material;
  if (p.name == "beta" || p.name == "tau") {
    std::vector<double> values;
    for (const MaxwellBranchValues& b : m.branches)
      values.push_back(p.name == "beta" ? b.beta : b.tau_s);
    return values;
  }
  if ((p.name == "k1" || p.name == "k2") && !m.fibers) return {};
  const std::pair<const char*, double> scalars[] = {{"mu", m.mu_pa},
                                                    {"k", m.k_pa},
                                                    {"k1", m.k1_pa},
                                                    {"k2", m.k2},
                                                    {"beta_vol", m.beta_vol},
                                                    {"tone", m.tone_pa},
                                                    {"contractility", m.contractility_pa},
                                                    {"optimal_stretch", m.optimal_stretch},
                                                    {"stretch_width", m.stretch_width},
                                                    {"hill_a", m.hill_a},
                                                    {"hill_vmax", m.hill_vmax_per_s}};
  for (const auto& [name, value] : scalars)
    if (p.name == name) return {value};
  fail("parameter catalogue", "no model card field for " + p.name);
}

}  // namespace vesica::simulate
