// The material registry: one line per material name. Parameters are SI (Pa, s), and every
// one has a default here, the only place (the executables pass a parameter only when it is
// given). All laws are the decoupled family of DecoupledMaxwell.h:
//   neo-hookean: mu, K or K_per_mu (default K = 1000 mu), beta_vol (9; 0 = K/2 (ln J)²,
//                FEBio's law)
//   maxwell:     neo-hookean + beta1..beta5, tau1..tau5 (or beta, tau for one branch);
//                without any, the thesis's one branch beta 0.15, tau 1e-4 s
//   fibers:      maxwell without default branches + k1 (Pa), k2 (-) on the full I4
//   bladder:     the normal adult detrusor (docs/simulate.md, "Default walls"): fibers,
//                one Maxwell branch, resting tone and contractility
//   neobladder:  an ileal neobladder: a soft fiber wall without coordinated contraction
// and every law takes the detrusor muscle's parameters (DetrusorMuscle.h): tone,
// contractility (Pa), optimal_stretch, stretch_width, hill_a, hill_vmax (1/s).
#include <algorithm>
#include <string>

#include "materials/DecoupledMaxwell.h"
#include "vesica/core/Error.h"
#include "vesica/simulate/materials/MaterialRegistry.h"

namespace vesica::simulate {
namespace {

// A law's defaults: what a material name means before its parameters are given.
struct LawDefaults {
  double mu = 5e3;
  bool fibers = false;
  double k1 = 10e3, k2 = 1.0;
  std::vector<MaxwellBranch> branches;  // replaced as a whole by given branches
  MuscleParameters muscle;
};

// The normal adult detrusor (docs/simulate.md, "Default walls"): passive parameters fitted
// to the shared normal recording on the real CT bladder, rate dependence and muscle from
// the literature cited there.
LawDefaults bladder_defaults() {
  LawDefaults d;
  d.mu = 1e3;
  d.fibers = true;
  d.k1 = 60.0;
  d.k2 = 0.045;
  d.branches = {{0.2, 10.0}};
  d.muscle.contractility = 100e3;
  d.muscle.optimal_stretch = 3.0;
  d.muscle.stretch_width = 1.5;
  d.muscle.hill_a = 0.3;
  d.muscle.hill_vmax = 0.073;
  return d;
}

// The ileal neobladder (docs/simulate.md, "Default walls"): a soft, slowly stiffening
// ileal wall that holds a reservoir's volume at a few cmH2O when its stress-free volume is
// its retracted tissue's (residual_fraction), the intestine's stress relaxation of
// seconds, and no coordinated contraction: it is voided by straining.
LawDefaults neobladder_defaults() {
  LawDefaults d;
  d.mu = 2e3;
  d.fibers = true;
  d.k1 = 200.0;
  d.k2 = 0.045;
  d.branches = {{0.2, 10.0}};
  return d;
}

OgdenVolumetric volumetric_from(ParamReader& p, double mu) {
  const bool ratio = p.has("K_per_mu");
  if (ratio && p.has("K")) usage_error("material parameters K and K_per_mu exclude each other");
  // Nearly incompressible by default: the wall is mostly water (docs/physics.md §2.7).
  const double K = p.has("K") ? p.positive("K", 0.0) : p.positive("K_per_mu", 1e3) * mu;
  // beta_vol = 0: K/2 (ln J)², FEBio's volumetric law (docs/physics.md §2.3).
  const double beta = p.get("beta_vol", 9.0);
  if (!(beta >= 0.0)) usage_error("material parameter beta_vol must be >= 0");
  return OgdenVolumetric(K, beta);
}

std::vector<MaxwellBranch> branches_from(ParamReader& p, std::vector<MaxwellBranch> branches) {
  bool given = false;
  std::vector<MaxwellBranch> read;
  if (p.has("beta") || p.has("tau")) {
    read.push_back({p.get("beta", 0.15), p.positive("tau", 1e-4)});
    given = true;
  }
  for (int a = 1; a <= 5; ++a) {
    const std::string b = "beta" + std::to_string(a), t = "tau" + std::to_string(a);
    if (p.has(b) || p.has(t)) {
      read.push_back({p.get(b, 0.0), p.positive(t, 1.0)});
      given = true;
    }
  }
  if (given) branches = read;
  for (const MaxwellBranch& br : branches)
    if (br.beta < 0.0) usage_error("material parameter beta must be >= 0");
  if (branches.size() > 5) usage_error("at most 5 Maxwell branches are supported");
  return branches;
}

std::optional<DetrusorMuscle> muscle_from(ParamReader& p, MuscleParameters m) {
  auto non_negative = [&p](const std::string& key, double fallback) {
    const double v = p.get(key, fallback);
    if (!(v >= 0.0)) usage_error("material parameter " + key + " must be >= 0");
    return v;
  };
  m.tone = non_negative("tone", m.tone);
  m.contractility = non_negative("contractility", m.contractility);
  m.optimal_stretch = p.positive("optimal_stretch", m.optimal_stretch);
  m.stretch_width = p.positive("stretch_width", m.stretch_width);
  m.hill_a = p.positive("hill_a", m.hill_a);
  m.hill_vmax = p.positive("hill_vmax", m.hill_vmax);
  const DetrusorMuscle muscle(m);
  if (!muscle.active()) return std::nullopt;
  return muscle;
}

std::unique_ptr<Material> make_decoupled(const MaterialSpec& spec, const LawDefaults& d) {
  ParamReader p(spec);
  const double mu = p.positive("mu", d.mu);
  std::unique_ptr<IsochoricPart> iso;
  if (d.fibers)
    iso = std::make_unique<FiberFamilies>(mu, p.get("k1", d.k1), p.positive("k2", d.k2));
  else
    iso = std::make_unique<NeoHookeanIsochoric>(mu);
  OgdenVolumetric volumetric = volumetric_from(p, mu);
  std::vector<MaxwellBranch> branches = branches_from(p, d.branches);
  std::optional<DetrusorMuscle> muscle = muscle_from(p, d.muscle);
  p.check_known_params();
  return std::make_unique<DecoupledMaxwell>(volumetric, std::move(iso), std::move(branches),
                                            std::move(muscle));
}

const std::map<std::string, MaterialFactory>& registry() {
  static const std::map<std::string, MaterialFactory> r = {
      {"neo-hookean", [](const MaterialSpec& s) { return make_decoupled(s, LawDefaults{}); }},
      {"maxwell",
       [](const MaterialSpec& s) {
         LawDefaults d;
         d.branches = {{0.15, 1e-4}};  // the thesis's fit (docs/physics.md §2.7)
         return make_decoupled(s, d);
       }},
      {"fibers",
       [](const MaterialSpec& s) {
         LawDefaults d;
         d.fibers = true;
         return make_decoupled(s, d);
       }},
      {"bladder", [](const MaterialSpec& s) { return make_decoupled(s, bladder_defaults()); }},
      {"neobladder",
       [](const MaterialSpec& s) { return make_decoupled(s, neobladder_defaults()); }},
  };
  return r;
}

}  // namespace

double ParamReader::get(const std::string& key, double fallback) {
  known_.push_back(key);
  const auto it = spec_.params.find(key);
  return it == spec_.params.end() ? fallback : it->second;
}

double ParamReader::positive(const std::string& key, double fallback) {
  const double v = get(key, fallback);
  if (!(v > 0.0)) usage_error("material '" + spec_.name + "' parameter " + key + " must be > 0");
  return v;
}

void ParamReader::check_known_params() const {
  for (const auto& [key, value] : spec_.params)
    if (std::find(known_.begin(), known_.end(), key) == known_.end())
      usage_error("material '" + spec_.name + "' has no parameter '" + key + "'");
}

std::unique_ptr<Material> make_material(const MaterialSpec& spec) {
  const auto it = registry().find(spec.name);
  if (it == registry().end()) {
    std::string names;
    for (const std::string& n : material_names()) names += (names.empty() ? "" : ", ") + n;
    usage_error("unknown material '" + spec.name + "'", "choose one of: " + names);
  }
  return it->second(spec);
}

std::vector<std::string> material_names() {
  std::vector<std::string> names;
  for (const auto& [name, factory] : registry()) names.push_back(name);
  return names;
}

}  // namespace vesica::simulate
