#pragma once
// The calibration driver (docs/physics.md §9), written against ModelSimulator so that any
// model can be fitted:
//  1. surrogate search (when a surrogate is given): Levenberg–Marquardt on the fast
//     surrogate from the start values and from `starts - 1` more points of a Halton
//     sequence in the box start · [1/4, 4] (within the bounds), in u = ln p;
//  2. model refinement: output space mapping from the best surrogate optimum the model can
//     run: with d = r_model(p_k) − r_surrogate(p_k), p_k+1 minimises |r_surrogate(p) + d|
//     (on the surrogate again), accepted while the model's own residual falls. Without a
//     surrogate, Levenberg–Marquardt on the model directly;
//  3. intervals and identifiability (ParameterUncertainty.h) from the model's Jacobian at
//     the optimum, or the surrogate's when the model's budget is spent (said so);
//  4. the fitted values re-run by `final_model` (the whole data: filling to the recording's
//     capacity, and voiding when fitted); the fit is only a fit when that run gets there.
// A failed run (CalibrationTargets.h) is a failed evaluation, penalised; when every run
// failed the result says so and keeps the start values.
#include <string>
#include <vector>

#include "vesica/compare/calibration/CalibrationResult.h"
#include "vesica/compare/calibration/CalibrationTargets.h"
#include "vesica/compare/calibration/FitParameter.h"
#include "vesica/compare/calibration/ModelRun.h"

namespace vesica::compare {

struct FitBudget {
  int surrogate_starts = 16;
  int surrogate_simulations = 4000;  // all starts and the mappings together (0-D: ms each)
  int model_simulations = 40;        // the reported model, Jacobian included
  int mapping_iterations = 4;
};

struct FitProblem {
  std::vector<FitParameter> parameters;
  CalibrationTargets targets;
  ModelSimulator model;        // the reported model (the 3-D wall)
  ModelSimulator surrogate;    // empty: no surrogate stage
  ModelSimulator final_model;  // the whole data; empty: `model`
  std::string model_name = "model", surrogate_name = "surrogate";
  FitBudget budget;
};

struct FitOutcome {
  CalibrationResult result;
  ModelRun final_run;  // the fitted model over the whole data
};

FitOutcome fit_parameters(const FitProblem& problem);

}  // namespace vesica::compare
