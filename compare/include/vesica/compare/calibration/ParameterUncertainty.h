#pragma once
// How well the data fix each fitted parameter (docs/physics.md §9), from the Jacobian of
// the scaled residuals at the optimum with respect to u = ln p:
//  - noise σ² = max(Σr²/(n − m), 1/12): the residual variance, but never below the
//    rounding noise of readings given to whole units of their scale;
//  - covariance of u = σ² (JᵀJ)⁻¹ through the SVD of J; a direction with a singular value
//    below 10⁻⁸ of the largest is not determined, and a parameter in it has no finite error;
//  - 95 % interval p·exp(±1.96 se(u)), within the bounds (it stays positive);
//  - sensitivity: RMS change of the scaled residuals when p grows by 10 %.
// A parameter is identifiable when the data depend on it (sensitivity ≥ 10⁻⁴), its error is
// finite and its interval spans less than a factor of 10; otherwise its interval is its
// search range and the reason says why. Fewer readings than parameters fix none.
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "vesica/compare/calibration/FitParameter.h"

namespace vesica::compare {

struct ParameterUncertainty {
  double standard_error = 0;       // of p (delta method: p · se(u)); +inf when not determined
  double ci_low = 0, ci_high = 0;  // 95 %
  double sensitivity = 0;          // RMS of the scaled residuals' change for p · 1.1
  bool identifiable = false;
  bool at_bound = false;  // the fit ended on a search bound
  std::string reason;     // why not identifiable; or a note (correlation, bound)
};

// J: rows = compared residuals (scaled), columns = parameters (∂r/∂ln p); r: the residuals.
std::vector<ParameterUncertainty> parameter_uncertainty(const Eigen::MatrixXd& J,
                                                        const Eigen::VectorXd& r,
                                                        const std::vector<FitParameter>& params,
                                                        const std::vector<double>& values);

}  // namespace vesica::compare
