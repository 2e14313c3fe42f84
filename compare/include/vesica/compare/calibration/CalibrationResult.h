#pragma once
// What a calibration reports (docs/physics.md §9): fitted values with 95 % intervals and
// whether the data identify them; per series of the data its RMSE beside the constant and
// straight-line baselines; the stages and their simulations (failures counted, never
// hidden); the verdict; the fitted curves and the voiding read-outs for the report.
// Independent of the simulator (the model card is simulate's core-only record), so that the
// report can show it without linking simulate.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vesica/compare/analysis/IcsParameters.h"
#include "vesica/compare/analysis/VoidingAgreement.h"
#include "vesica/simulate/ModelCard.h"

namespace vesica::compare {

struct FittedParameter {
  std::string name;  // mu, k1, p_open, ...
  std::string unit;  // kPa, -, s, ...
  double initial = 0, lower = 0, upper = 0;
  double value = 0;
  double ci_low = 0, ci_high = 0;  // 95 %; the search range when not identifiable
  double standard_error = 0;       // +inf when the data do not determine it
  double sensitivity = 0;          // RMS change of the scaled residuals for a 10 % change
  bool identifiable = false;
  std::string note;  // why not identifiable; correlations; "at its upper bound"
};

// One series of the data (filling Pdet, voiding flow, ...) against the fitted model.
struct SeriesFit {
  std::string name, unit, abscissa;
  std::size_t points = 0;  // readings compared
  double rmse = 0, max_abs_error = 0;
  double constant_rmse = 0, line_rmse = 0;  // baselines over the same readings
  bool beats_line = false;                  // rmse < line_rmse
  Curve measured, simulated;                // at the readings (simulated NaN: not compared)
};

// One stage of the fit: the surrogate's global search or the model's refinement.
struct CalibrationStage {
  std::string name;   // "surrogate search", "model refinement"
  std::string model;  // what was simulated
  int simulations = 0, failed = 0;
  double seconds = 0;
  double cost = 0;  // sum of squared scaled residuals at the stage's best point
};

struct CalibrationResult {
  std::vector<FittedParameter> parameters;
  double volume_lo_ml = 0, volume_hi_ml = 0;       // filling volumes the fit compared
  double rmse_cmh2o = 0, max_abs_error_cmh2o = 0;  // of the filling Pdet series
  std::vector<SeriesFit> series;
  std::vector<CalibrationStage> stages;
  int simulations = 0;  // all stages
  int failed_simulations = 0;
  int iterations = 0;
  double seconds = 0;
  bool fitted = false;             // the fitted model reached the data's end and beats every line
  std::string status;              // the verdict, one sentence
  std::vector<std::string> notes;  // failures, unidentifiable parameters, the solver's end
  Curve fitted_filling;            // (volume ml, Pdet cmH2O) of the fitted model
  std::optional<VoidingAgreement> voiding;  // when voiding was fitted
  // The fitted model's card (the run of fitted_filling): fit/model.json, which
  // `vesica-simulate --model-card` runs again to the same curve.
  std::optional<simulate::ModelCard> fitted_card;
};

nlohmann::json to_json(const CalibrationResult& r);

}  // namespace vesica::compare
