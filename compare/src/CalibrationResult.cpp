#include "vesica/compare/CalibrationResult.h"

namespace vesica::compare {

nlohmann::json to_json(const CalibrationResult& r) {
  nlohmann::json params = nlohmann::json::array();
  for (const auto& p : r.parameters)
    params.push_back({{"name", p.name},
                      {"unit", p.unit},
                      {"initial", p.initial},
                      {"lower_bound", p.lower},
                      {"upper_bound", p.upper},
                      {"value", p.value},
                      {"standard_error", p.standard_error},
                      {"ci95_low", p.ci_low},
                      {"ci95_high", p.ci_high}});
  return {{"parameters", params},         {"volume_range_ml", {r.volume_lo_ml, r.volume_hi_ml}},
          {"rmse_cmh2o", r.rmse_cmh2o},   {"max_abs_error_cmh2o", r.max_abs_error_cmh2o},
          {"simulations", r.simulations}, {"iterations", r.iterations},
          {"seconds", r.seconds},         {"status", r.status}};
}

}  // namespace vesica::compare
