#pragma once
// The two fits a calibration must beat to be called a fit (docs/physics.md §9): the best
// constant (the mean of the readings) and the best straight line in the abscissa (least
// squares). With recordings rounded to whole cmH2O and a dozen rows, a flat or straight
// Pdet(V) already comes close, so a model's RMSE means little without them.
#include <vector>

namespace vesica::compare {

struct BaselineRmse {
  double constant = 0;  // RMSE of y about its mean
  double line = 0;      // RMSE of y about its least-squares line in x (the constant's
                        // RMSE when all x are equal)
};

// Needs at least one point; x and y of equal length.
BaselineRmse baseline_rmse(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace vesica::compare
