#pragma once
// What vesica-simulate's parameter table (SimulateParameters.h) fills: the wall material as
// the command line names it (clinical units), how the imaged wall becomes the reference,
// the protocol and how it is computed. Header-only settings (std and Eigen), so that the
// table's library links core only.
#include <map>
#include <string>
#include <vector>

#include "vesica/simulate/protocol/CystometrySettings.h"
#include "vesica/simulate/verification/VerificationSettings.h"
#include "vesica/simulate/wall/WallLoading.h"

namespace vesica::simulate {

// A material parameter not given: the material's own default (ParameterCatalogue.h).
constexpr double kMaterialDefault = -1.0;

// The wall material as the parameter table takes it (docs/physics.md §2): the named
// material and the parameters given, each by its catalogue name in its catalogue unit
// (kPa where the library takes Pa). A parameter not given (kMaterialDefault, or no Maxwell
// branch list) is the named material's own; material_spec() (SimulateParameters.h) turns
// it into the library's MaterialSpec.
struct MaterialChoice {
  std::string name = "bladder";
  std::map<std::string, double> values;                 // mu, k, k1, ..., contractility, ...
  std::map<std::string, std::vector<double>> branches;  // beta, tau: one per Maxwell branch

  bool given(const std::string& parameter) const {
    const auto v = values.find(parameter);
    if (v != values.end()) return v->second != kMaterialDefault;
    const auto b = branches.find(parameter);
    return b != branches.end() && !b->second.empty();
  }
};

struct SimulateSettings {
  MaterialChoice material;
  WallOptions wall;           // thickness, reference state, residual volume
  ProtocolSettings protocol;  // the cystometry and the surroundings
  // One posture for both: the wall's fixed patch (WallOptions) and gravity (ProtocolSettings).
  Posture posture = Posture::Supine;
  RunOptions run;  // level, dynamics, level-2 steps, series
  // Issue 25: the verification protocols and the FEBio export.
  VerificationSettings verification;
  std::string export_feb;  // empty = none
  // FEBio's nearest law, with a warning, where it has none equal to vesica's (FebioExport.h).
  bool febio_approximate = false;
};

}  // namespace vesica::simulate
