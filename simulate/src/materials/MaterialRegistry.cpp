// The material registry: a spec resolved against the parameter catalogue's defaults of its
// named material, then the law built from the resolved values (MaterialRegistry.h).
#include "vesica/simulate/materials/MaterialRegistry.h"

#include <algorithm>
#include <string>

#include "materials/DecoupledMaxwell.h"
#include "vesica/core/Error.h"
#include "vesica/simulate/ParameterCatalogue.h"

namespace vesica::simulate {
namespace {

constexpr int kMaxBranches = 5;  // Maxwell branches a material takes (docs/physics.md §2.4)

// The catalogue's default of one parameter for this material (SI).
std::vector<double> default_of(const std::string& name, const std::string& material,
                               double mu_pa = 0.0) {
  return catalogue_parameter(name).default_si(material, mu_pa);
}

double scalar_default(const std::string& name, const std::string& material) {
  return default_of(name, material).front();
}

void resolve_volumetric(ParamReader& p, MaterialCard& m) {
  const bool ratio = p.has("K_per_mu");
  if (ratio && p.has("K")) usage_error("material parameters K and K_per_mu exclude each other");
  // Nearly incompressible by default: the wall is mostly water (docs/physics.md §2.7).
  const double per_mu = catalogue_parameter("k").default_per_mu;
  m.k_pa = p.has("K") ? p.positive("K", 0.0) : p.positive("K_per_mu", per_mu) * m.mu_pa;
  // beta_vol = 0: K/2 (ln J)², FEBio's volumetric law (docs/physics.md §2.3).
  m.beta_vol = p.get("beta_vol", scalar_default("beta_vol", m.name));
  if (!(m.beta_vol >= 0.0)) usage_error("material parameter beta_vol must be >= 0");
}

// The branch a given beta or tau without its other half takes it from: the material's own
// branch a, else the thesis's branch of the maxwell material.
MaxwellBranchValues fallback_branch(const std::string& material, std::size_t a) {
  const std::vector<double> beta = default_of("beta", material), tau = default_of("tau", material);
  if (a < beta.size()) return {beta[a], tau[a]};
  return {default_of("beta", "maxwell").front(), default_of("tau", "maxwell").front()};
}

void resolve_branches(ParamReader& p, MaterialCard& m) {
  if (!catalogue_parameter("beta").applies_to(m.name)) return;  // an elastic law
  const std::vector<double> beta = default_of("beta", m.name), tau = default_of("tau", m.name);
  for (std::size_t a = 0; a < beta.size(); ++a) m.branches.push_back({beta[a], tau[a]});
  std::vector<MaxwellBranchValues> given;
  for (int a = 1; a <= kMaxBranches; ++a) {
    // "beta"/"tau" spell the first branch.
    std::string b = "beta" + std::to_string(a), t = "tau" + std::to_string(a);
    if (a == 1 && (p.has("beta") || p.has("tau"))) {
      if (p.has(b) || p.has(t)) usage_error("material parameters beta/tau and beta1/tau1 are one");
      b = "beta";
      t = "tau";
    }
    if (!p.has(b) && !p.has(t)) continue;
    const MaxwellBranchValues fallback = fallback_branch(m.name, given.size());
    given.push_back({p.get(b, fallback.beta), p.positive(t, fallback.tau_s)});
  }
  if (!given.empty()) m.branches = given;
  for (const MaxwellBranchValues& br : m.branches)
    if (br.beta < 0.0) usage_error("material parameter beta must be >= 0");
}

void resolve_muscle(ParamReader& p, MaterialCard& m) {
  auto non_negative = [&](const std::string& key) {
    const double v = p.get(key, scalar_default(key, m.name));
    if (!(v >= 0.0)) usage_error("material parameter " + key + " must be >= 0");
    return v;
  };
  auto positive = [&](const std::string& key) {
    return p.positive(key, scalar_default(key, m.name));
  };
  m.tone_pa = non_negative("tone");
  m.contractility_pa = non_negative("contractility");
  m.optimal_stretch = positive("optimal_stretch");
  m.stretch_width = positive("stretch_width");
  m.hill_a = positive("hill_a");
  m.hill_vmax_per_s = positive("hill_vmax");
}

std::string names_text() {
  std::string names;
  for (const std::string& n : material_names()) names += (names.empty() ? "" : ", ") + n;
  return names;
}

}  // namespace

MaterialCard resolve_material(const MaterialSpec& spec) {
  const NamedMaterial* named = find_named_material(spec.name);
  if (!named) usage_error("unknown material '" + spec.name + "'", "choose one of: " + names_text());
  ParamReader p(spec);
  MaterialCard m;
  m.name = spec.name;
  m.mu_pa = p.positive("mu", scalar_default("mu", m.name));
  resolve_volumetric(p, m);
  m.fibers = named->fibers;
  if (m.fibers) {
    m.k1_pa = p.get("k1", scalar_default("k1", m.name));
    m.k2 = p.positive("k2", scalar_default("k2", m.name));
  }
  resolve_branches(p, m);
  resolve_muscle(p, m);
  p.check_known_params();
  return m;
}

std::unique_ptr<Material> build_material(const MaterialCard& m) {
  std::unique_ptr<IsochoricPart> iso;
  if (m.fibers)
    iso = std::make_unique<FiberFamilies>(m.mu_pa, m.k1_pa, m.k2);
  else
    iso = std::make_unique<NeoHookeanIsochoric>(m.mu_pa);
  if (m.branches.size() > kMaxBranches) usage_error("at most 5 Maxwell branches are supported");
  std::vector<MaxwellBranch> branches;
  for (const MaxwellBranchValues& b : m.branches) branches.push_back({b.beta, b.tau_s});
  std::optional<DetrusorMuscle> muscle;
  if (m.has_muscle()) {
    MuscleParameters mp;
    mp.tone = m.tone_pa;
    mp.contractility = m.contractility_pa;
    mp.optimal_stretch = m.optimal_stretch;
    mp.stretch_width = m.stretch_width;
    mp.hill_a = m.hill_a;
    mp.hill_vmax = m.hill_vmax_per_s;
    muscle = DetrusorMuscle(mp);
  }
  return std::make_unique<DecoupledMaxwell>(OgdenVolumetric(m.k_pa, m.beta_vol), std::move(iso),
                                            std::move(branches), muscle);
}

std::unique_ptr<Material> make_material(const MaterialSpec& spec) {
  return build_material(resolve_material(spec));
}

MaterialSpec material_spec(const MaterialCard& m) {
  MaterialSpec spec{m.name, {{"mu", m.mu_pa}, {"K", m.k_pa}, {"beta_vol", m.beta_vol}}};
  if (m.fibers) {
    spec.params["k1"] = m.k1_pa;
    spec.params["k2"] = m.k2;
  }
  for (std::size_t a = 0; a < m.branches.size(); ++a) {
    spec.params["beta" + std::to_string(a + 1)] = m.branches[a].beta;
    spec.params["tau" + std::to_string(a + 1)] = m.branches[a].tau_s;
  }
  spec.params["tone"] = m.tone_pa;
  spec.params["contractility"] = m.contractility_pa;
  spec.params["optimal_stretch"] = m.optimal_stretch;
  spec.params["stretch_width"] = m.stretch_width;
  spec.params["hill_a"] = m.hill_a;
  spec.params["hill_vmax"] = m.hill_vmax_per_s;
  return spec;
}

std::vector<std::string> material_names() {
  std::vector<std::string> names;
  for (const NamedMaterial& m : named_materials()) names.push_back(m.name);
  std::sort(names.begin(), names.end());  // alphabetical, as they always were listed
  return names;
}

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

}  // namespace vesica::simulate
