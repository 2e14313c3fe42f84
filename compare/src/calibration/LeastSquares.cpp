#include "calibration/LeastSquares.h"

#include <algorithm>
#include <cmath>

#include <unsupported/Eigen/NonLinearOptimization>

namespace vesica::compare {
namespace {

// The solver's unknowns z map onto u = ln p within the bounds [a, b] by
// u = a + (b − a)(1 + sin z)/2 (the bounded transform of MINUIT): smooth and unbounded in z,
// so that the solver never steps into the flat region a clamp would make beyond a bound.
struct BoundedLog {
  Eigen::VectorXd a, b;
  explicit BoundedLog(const std::vector<FitParameter>& params)
      : a(static_cast<Eigen::Index>(params.size())), b(a.size()) {
    for (Eigen::Index j = 0; j < a.size(); ++j) {
      a[j] = std::log(params[static_cast<std::size_t>(j)].lower);
      b[j] = std::log(params[static_cast<std::size_t>(j)].upper);
    }
  }
  Eigen::VectorXd u(const Eigen::VectorXd& z) const {
    return a.array() + (b - a).array() * (1 + z.array().sin()) / 2;
  }
  Eigen::VectorXd du_dz(const Eigen::VectorXd& z) const {
    return ((b - a).array() * z.array().cos() / 2).matrix();
  }
  // A start on a bound would have du/dz = 0 there and never leave it: start just inside.
  Eigen::VectorXd z(const Eigen::VectorXd& u) const {
    Eigen::VectorXd z(u.size());
    for (Eigen::Index j = 0; j < u.size(); ++j) {
      const double s = b[j] > a[j] ? 2 * (u[j] - a[j]) / (b[j] - a[j]) - 1 : 0.0;
      z[j] = std::asin(std::clamp(s, -0.999, 0.999));
    }
    return z;
  }
};

// Eigen's functor interface in z; a spent budget asks the solver to stop (a negative return).
struct Functor {
  using Scalar = double;
  FitObjective& objective;
  const BoundedLog& map;
  int operator()(const Eigen::VectorXd& z, Eigen::VectorXd& f) const {
    const auto r = objective.residuals(map.u(z));
    if (!r) return -1;
    f = *r;
    return 0;
  }
  int df(const Eigen::VectorXd& z, Eigen::MatrixXd& J) const {
    const auto j = objective.jacobian(map.u(z));
    if (!j) return -1;
    J = *j * map.du_dz(z).asDiagonal();
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
  const BoundedLog map(objective.parameters());
  Functor functor{objective, map};
  Eigen::LevenbergMarquardt<Functor> lm(functor);
  lm.parameters.maxfev = std::max(2, max_simulations);
  lm.parameters.xtol = 1e-3;
  lm.parameters.ftol = 1e-4;
  Eigen::VectorXd z = map.z(u0);
  const auto status = lm.minimize(z);
  objective.set_budget(saved);
  out.u = objective.u_of(objective.values(map.u(z)));
  out.iterations = static_cast<int>(lm.iter);
  out.status = status_text(status);
  return out;
}

}  // namespace vesica::compare
