// The material registry: one line per material name. Parameters are SI (Pa, s):
//   neo-hookean: mu, K (10 kPa) or K_per_mu (K = K_per_mu * mu, follows a fitted mu),
//                beta_vol (9; 0 = K/2 (ln J)², FEBio's law)
//   maxwell:     neo-hookean + beta1..beta5, tau1..tau5 (or beta, tau for one branch)
//   fibers:      maxwell + k1 (Pa), k2 (-); fibers are viscoelastic with the same branches
#include <algorithm>
#include <string>

#include "DecoupledMaxwell.h"
#include "vesica/core/Error.h"
#include "vesica/simulate/MaterialRegistry.h"

namespace vesica::simulate {
namespace {

OgdenVolumetric volumetric_from(ParamReader& p, double mu) {
  const bool ratio = p.has("K_per_mu");
  if (ratio && p.has("K")) usage_error("material parameters K and K_per_mu exclude each other");
  const double K = ratio ? p.positive("K_per_mu", 1e3) * mu : p.positive("K", 10e3);
  // beta_vol = 0: K/2 (ln J)², FEBio's volumetric law (docs/physics.md §2.3).
  const double beta = p.get("beta_vol", 9.0);
  if (!(beta >= 0.0)) usage_error("material parameter beta_vol must be >= 0");
  return OgdenVolumetric(K, beta);
}

std::vector<MaxwellBranch> branches_from(ParamReader& p) {
  std::vector<MaxwellBranch> branches;
  if (p.has("beta") || p.has("tau"))
    branches.push_back({p.get("beta", 0.15), p.positive("tau", 1e-4)});
  for (int a = 1; a <= 5; ++a) {
    const std::string b = "beta" + std::to_string(a), t = "tau" + std::to_string(a);
    if (p.has(b) || p.has(t)) branches.push_back({p.get(b, 0.0), p.positive(t, 1.0)});
  }
  for (const MaxwellBranch& br : branches)
    if (br.beta < 0.0) usage_error("material parameter beta must be >= 0");
  if (branches.size() > 5) usage_error("at most 5 Maxwell branches are supported");
  return branches;
}

std::unique_ptr<Material> make_neo_hookean(const MaterialSpec& spec) {
  ParamReader p(spec);
  const double mu = p.positive("mu", 5e3);
  auto m = std::make_unique<DecoupledMaxwell>(volumetric_from(p, mu),
                                              std::make_unique<NeoHookeanIsochoric>(mu),
                                              std::vector<MaxwellBranch>{});
  p.check_known_params();
  return m;
}

std::unique_ptr<Material> make_maxwell(const MaterialSpec& spec) {
  ParamReader p(spec);
  const double mu = p.positive("mu", 5e3);
  auto iso = std::make_unique<NeoHookeanIsochoric>(mu);
  auto m =
      std::make_unique<DecoupledMaxwell>(volumetric_from(p, mu), std::move(iso), branches_from(p));
  p.check_known_params();
  return m;
}

std::unique_ptr<Material> make_fibers(const MaterialSpec& spec) {
  ParamReader p(spec);
  const double mu = p.positive("mu", 5e3);
  auto iso = std::make_unique<FiberFamilies>(mu, p.get("k1", 10.0), p.positive("k2", 1.0));
  auto m =
      std::make_unique<DecoupledMaxwell>(volumetric_from(p, mu), std::move(iso), branches_from(p));
  p.check_known_params();
  return m;
}

const std::map<std::string, MaterialFactory>& registry() {
  static const std::map<std::string, MaterialFactory> r = {
      {"neo-hookean", make_neo_hookean},
      {"maxwell", make_maxwell},
      {"fibers", make_fibers},
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
