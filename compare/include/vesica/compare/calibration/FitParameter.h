#pragma once
// One model parameter a calibration fits, in the unit it is reported in (kPa, cmH2O s/ml,
// ...), with its search bounds and the phase of the cystometry it acts on. Independent of
// the simulator: the fit driver, the statistics and the report see only these.
#include <string>

namespace vesica::compare {

struct FitParameter {
  std::string name, unit;
  double initial = 1.0, lower = 0.0, upper = 0.0;  // initial within [lower, upper], all > 0
  bool voiding = false;  // acts on voiding only: fitting it needs the voiding data
};

}  // namespace vesica::compare
