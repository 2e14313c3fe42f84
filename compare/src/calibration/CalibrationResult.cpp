#include "vesica/compare/calibration/CalibrationResult.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "vesica/simulate/ModelCardJson.h"

namespace vesica::compare {
namespace {

// JSON has no infinity: an undetermined error is null.
nlohmann::json finite(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

nlohmann::json curve(const Curve& c) {
  nlohmann::json y = nlohmann::json::array();
  for (double v : c.y) y.push_back(finite(v));
  return {{"x", c.x}, {"y", y}};
}

nlohmann::json to_json(const FittedParameter& p) {
  return {{"name", p.name},
          {"unit", p.unit},
          {"initial", p.initial},
          {"lower_bound", p.lower},
          {"upper_bound", p.upper},
          {"value", p.value},
          {"standard_error", finite(p.standard_error)},
          {"ci95_low", p.ci_low},
          {"ci95_high", p.ci_high},
          {"sensitivity", p.sensitivity},
          {"identifiable", p.identifiable},
          {"note", p.note}};
}

nlohmann::json to_json(const SeriesFit& s) {
  return {{"name", s.name},
          {"unit", s.unit},
          {"abscissa", s.abscissa},
          {"points", s.points},
          {"rmse", s.rmse},
          {"max_abs_error", s.max_abs_error},
          {"constant_baseline_rmse", s.constant_rmse},
          {"line_baseline_rmse", s.line_rmse},
          {"beats_line", s.beats_line},
          {"measured", curve(s.measured)},
          {"simulated", curve(s.simulated)}};
}

nlohmann::json to_json(const CalibrationStage& s) {
  return {{"name", s.name},     {"model", s.model},     {"simulations", s.simulations},
          {"failed", s.failed}, {"seconds", s.seconds}, {"cost", s.cost}};
}

template <class T>
nlohmann::json array_of(const std::vector<T>& items) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& i : items) a.push_back(to_json(i));
  return a;
}

}  // namespace

nlohmann::json to_json(const CalibrationResult& r) {
  return {
      {"parameters", array_of(r.parameters)},
      {"volume_range_ml", {r.volume_lo_ml, r.volume_hi_ml}},
      {"rmse_cmh2o", r.rmse_cmh2o},
      {"max_abs_error_cmh2o", r.max_abs_error_cmh2o},
      {"series", array_of(r.series)},
      {"stages", array_of(r.stages)},
      {"simulations", r.simulations},
      {"failed_simulations", r.failed_simulations},
      {"iterations", r.iterations},
      {"seconds", r.seconds},
      {"fitted", r.fitted},
      {"status", r.status},
      {"notes", r.notes},
      {"voiding", r.voiding ? to_json(*r.voiding) : nlohmann::json()},
      {"fitted_filling", {{"volume_ml", r.fitted_filling.x}, {"pdet_cmh2o", r.fitted_filling.y}}},
      {"model_card", r.fitted_card ? nlohmann::json(*r.fitted_card) : nlohmann::json()}};
}

}  // namespace vesica::compare
