#pragma once
// Levenberg–Marquardt (Eigen's MINPACK port, unsupported/NonLinearOptimization) over a
// FitObjective, within the parameters' bounds (a smooth bounded transform of u = ln p),
// stopped by the objective's simulation budget.
#include <string>

#include <Eigen/Dense>

#include "calibration/FitObjective.h"

namespace vesica::compare {

struct LeastSquaresOutcome {
  Eigen::VectorXd u;  // the best point the solver accepted
  int iterations = 0;
  std::string status;  // the solver's verdict
};

// xtol 1e-3 (0.1 % of the parameters), ftol 1e-4; at most `max_simulations` new runs.
LeastSquaresOutcome least_squares(FitObjective& objective, const Eigen::VectorXd& u0,
                                  int max_simulations);

}  // namespace vesica::compare
