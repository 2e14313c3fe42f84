#pragma once
// Materials by name (ParameterCatalogue.h's named materials). A MaterialSpec names the
// material and gives some of its parameters (SI, by their MaterialSpec keys); every other
// parameter is the named material's default from the parameter catalogue, the one place
// defaults live. resolve_material() says what a spec means, every value resolved (the
// model card's material); make_material() builds the law from that (build_material()). All laws are
// the decoupled family of DecoupledMaxwell.h (docs/physics.md §2):
//   neo-hookean: mu, K or K_per_mu (K = 1000 mu unless given), beta_vol
//   maxwell:     neo-hookean + Maxwell branches beta1..beta5, tau1..tau5 (beta, tau: the first)
//   fibers:      neo-hookean + k1 (Pa), k2 (-) on the full I4, and branches
//   bladder:     the normal adult detrusor: fibers, one branch, a muscle
//   neobladder:  an ileal neobladder: a soft fiber wall without coordinated contraction
// and every law takes the detrusor muscle's parameters (DetrusorMuscle.h): tone,
// contractility (Pa), optimal_stretch, stretch_width, hill_a, hill_vmax (1/s). A given
// branch list replaces the material's as a whole; each branch's missing half is the
// material's (or the maxwell material's).
#include <memory>
#include <string>
#include <vector>

#include "vesica/simulate/ModelCard.h"
#include "vesica/simulate/materials/Material.h"

namespace vesica::simulate {

// Throws vesica::Error (usage) for an unknown name or an unknown/invalid parameter.
MaterialCard resolve_material(const MaterialSpec& spec);
std::unique_ptr<Material> make_material(const MaterialSpec& spec);
// The law of a resolved material (a model card's).
std::unique_ptr<Material> build_material(const MaterialCard& card);
// The spec that gives every parameter of the card: it builds the same material.
MaterialSpec material_spec(const MaterialCard& card);
std::vector<std::string> material_names();

// Reads spec.params[key] or a default; every key a material reads is "known", and
// check_known_params() rejects the rest so that typos do not pass silently.
class ParamReader {
 public:
  explicit ParamReader(const MaterialSpec& spec) : spec_(spec) {}
  double get(const std::string& key, double fallback);
  double positive(const std::string& key, double fallback);
  bool has(const std::string& key) const { return spec_.params.count(key) > 0; }
  void check_known_params() const;

 private:
  const MaterialSpec& spec_;
  std::vector<std::string> known_;
};

}  // namespace vesica::simulate
