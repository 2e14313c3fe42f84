#include "LeastSquares.h"

#include <algorithm>

#include <unsupported/Eigen/NonLinearOptimization>

namespace vesica::compare {
namespace {

// Eigen's functor interface; a spent budget asks the solver to stop (a negative return).
struct Functor {
  using Scalar = double;
  FitObjective& objective;
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& f) const {
    const auto r = objective.residuals(u);
    if (!r) return -1;
    f = *r;
    return 0;
  }
  int df(const Eigen::VectorXd& u, Eigen::MatrixXd& J) const {
    const auto j = objective.jacobian(u);
    if (!j) return -1;
    J = *j;
    return 0;
  }
  int inputs() const { return objective.inputs(); }
  int values() const { return objective.values_count(); }
};

std::string status_text(Eigen::LevenbergMarquardtSpace::Status s) {
  using namespace Eigen::LevenbergMarquardtSpace;
  switch (s) {
    case RelativeReductionTooSmall:
      return "converged (relative reduction of the residual)";
    case RelativeErrorTooSmall:
      return "converged (relative change of the parameters)";
    case RelativeErrorAndReductionTooSmall:
      return "converged (residual and parameters)";
    case CosinusTooSmall:
      return "converged (gradient orthogonal to the residual)";
    case TooManyFunctionEvaluation:
    case UserAsked:
      return "stopped: simulation budget reached";
    case FtolTooSmall:
    case XtolTooSmall:
    case GtolTooSmall:
      return "stopped: tolerance too small to improve further";
    default:
      return "stopped: solver status " + std::to_string(static_cast<int>(s));
  }
}

}  // namespace

LeastSquaresOutcome least_squares(FitObjective& objective, const Eigen::VectorXd& u0,
                                  int max_simulations) {
  LeastSquaresOutcome out;
  out.u = u0;
  if (objective.values_count() < objective.inputs()) {
    out.status = "not solved: fewer readings than parameters";
    return out;
  }
  const int saved = objective.budget();
  objective.set_budget(std::min(saved, objective.simulations() + max_simulations));
  Functor functor{objective};
  Eigen::LevenbergMarquardt<Functor> lm(functor);
  lm.parameters.maxfev = std::max(2, max_simulations);
  lm.parameters.xtol = 1e-3;
  lm.parameters.ftol = 1e-4;
  const auto status = lm.minimize(out.u);
  objective.set_budget(saved);
  out.iterations = static_cast<int>(lm.iter);
  out.status = status_text(status);
  return out;
}

}  // namespace vesica::compare
