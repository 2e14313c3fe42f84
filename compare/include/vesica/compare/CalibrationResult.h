#pragma once
// What a calibration reports: fitted values with 95 % confidence intervals, the fit's
// residual, and the fitted filling curve. Independent of the simulator, so that the
// report can show it without linking the simulate library.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/compare/IcsParameters.h"

namespace vesica::compare {

struct FittedParameter {
  std::string name;  // mu, beta, tau, k1, k2, r1, r2, p_open
  std::string unit;  // kPa, -, s, ...
  double initial = 0, lower = 0, upper = 0;
  double value = 0;
  double ci_low = 0, ci_high = 0;  // 95 % interval from sigma^2 (J^T J)^-1
  double standard_error = 0;
};

struct CalibrationResult {
  std::vector<FittedParameter> parameters;
  double volume_lo_ml = 0, volume_hi_ml = 0;  // volumes the fit compared
  double rmse_cmh2o = 0, max_abs_error_cmh2o = 0;
  int simulations = 0;
  int iterations = 0;
  double seconds = 0;
  std::string status;    // the solver's verdict
  Curve fitted_filling;  // (volume ml, Pdet cmH2O) of the fitted model
};

nlohmann::json to_json(const CalibrationResult& r);

}  // namespace vesica::compare
