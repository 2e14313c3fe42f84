#pragma once
// Materials by name. Adding a material is one file (the class and its factory) plus one
// registration line in MaterialRegistry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "vesica/simulate/materials/Material.h"

namespace vesica::simulate {

using MaterialFactory = std::function<std::unique_ptr<Material>(const MaterialSpec&)>;

// Throws vesica::Error (usage) for an unknown name or an unknown/invalid parameter.
std::unique_ptr<Material> make_material(const MaterialSpec& spec);
std::vector<std::string> material_names();

// Reads spec.params[key] or a default; every key a factory reads is "known", and
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
