#include "vesica/compare/Calibration.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include <Eigen/Dense>
#include <unsupported/Eigen/NonLinearOptimization>

#include "vesica/compare/ModelComparison.h"
#include "vesica/compare/PiecewiseLinear.h"
#include "vesica/compare/RecordingAnalysis.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"

namespace vesica::compare {
namespace {

constexpr double kFailedResidual = 100.0;  // cmH2O, where a run gave no curve at all

}  // namespace

Recording recording_from_history(const std::vector<simulate::HistoryRow>& h) {
  Recording r;
  r.source = "calibration run";
  for (const auto& row : h) {
    r.time_s.push_back(row.time_s);
    r.infused_ml.push_back(row.infused_ml);
    r.volume_ml.push_back(row.volume_ml);
    r.pves_cmh2o.push_back(row.pves_cmh2o);
    r.pabd_cmh2o.push_back(row.pabd_cmh2o);
    r.pdet_recorded_cmh2o.push_back(row.pdet_cmh2o);
    r.flow_ml_s.push_back(row.flow_ml_s);
    r.voided_ml.push_back(row.voided_ml);
  }
  return r;
}

namespace {

void apply(const ParameterSpec& s, double v, simulate::MaterialSpec& m,
           simulate::ProtocolSettings& p) {
  if (s.name == "mu") m.params["mu"] = v * 1e3;
  if (s.name == "k") {
    m.params.erase("K_per_mu");  // a fitted K no longer follows mu
    m.params["K"] = v * 1e3;
  }
  if (s.name == "beta") m.params["beta"] = v;
  if (s.name == "tau") m.params["tau"] = v;
  if (s.name == "k1") m.params["k1"] = v;
  if (s.name == "k2") m.params["k2"] = v;
  if (s.name == "r1") p.r1_cmh2o_s_per_ml = v;
  if (s.name == "r2") p.r2_cmh2o_s2_per_ml2 = v;
  if (s.name == "p_open") p.p_open_cmh2o = v;
}

// The residual function of the fit, in u = ln p, with a cache (LM evaluates the same
// point for the value and the Jacobian) and a budget of simulations.
class Residuals {
 public:
  explicit Residuals(const CalibrationProblem& problem) : pb_(problem) {
    grid_ = grid(pb_.volume_lo_ml, pb_.volume_hi_ml, pb_.volume_step_ml);
    const PiecewiseLinear m(pb_.measured_filling.x, pb_.measured_filling.y);
    for (double v : grid_) measured_.push_back(m(v));
    if (uses_flow() && pb_.measured_flow.x.size() > 1) {
      const PiecewiseLinear q(pb_.measured_flow.x, pb_.measured_flow.y);
      for (double t : compare::grid(0, pb_.measured_flow.x.back(), 1.0)) {
        flow_grid_.push_back(t);
        measured_.push_back(q(t));
      }
    }
  }

  bool uses_flow() const {
    return std::any_of(pb_.parameters.begin(), pb_.parameters.end(),
                       [](const ParameterSpec& s) { return s.outlet; });
  }
  int values() const { return static_cast<int>(measured_.size()); }
  int inputs() const { return static_cast<int>(pb_.parameters.size()); }
  int simulations() const { return simulations_; }
  std::size_t filling_points() const { return grid_.size(); }

  std::vector<double> parameters(const Eigen::VectorXd& u) const {
    std::vector<double> p(u.size());
    for (int j = 0; j < u.size(); ++j)
      p[j] = std::clamp(std::exp(u[j]), pb_.parameters[j].lower, pb_.parameters[j].upper);
    return p;
  }

  // Residual vector at u; also returns the simulated filling curve of that run.
  Eigen::VectorXd operator()(const Eigen::VectorXd& u, Curve* filling = nullptr) {
    const std::vector<double> p = parameters(u);
    const auto hit = cache_.find(p);
    if (hit != cache_.end() && !filling) return hit->second;
    simulate::MaterialSpec material = pb_.material;
    simulate::ProtocolSettings protocol = pb_.protocol;
    for (std::size_t j = 0; j < p.size(); ++j) apply(pb_.parameters[j], p[j], material, protocol);
    ++simulations_;
    // Every iteration a fresh tangent: the fit's finite-difference Jacobian needs curves
    // converged far below the Newton tolerance (quadratic convergence overshoots it), not
    // the chord iterations' just-below-tolerance ones, whose noise narrowed the confidence
    // interval past the truth.
    simulate::RunOptions run = pb_.run;
    run.newton.reuse_tangent_ratio = 0.0;
    const auto result = simulate::run_cystometry(pb_.wall, material, protocol, run);
    Eigen::VectorXd r = Eigen::VectorXd::Constant(values(), kFailedResidual);
    if (result.history.size() >= 2) {
      const auto a = analyse(recording_from_history(result.history));
      if (filling) *filling = a.filling;
      fill_residuals(a, r);
    }
    if (!result.completed) log()->warn("calibration run: {}", result.failure);
    cache_[p] = r;
    return r;
  }

  // Forward differences in u with a 1 % relative step of p (the simulation's Newton
  // tolerance makes smaller steps noisy).
  Eigen::MatrixXd jacobian(const Eigen::VectorXd& u) {
    const Eigen::VectorXd f0 = (*this)(u);
    Eigen::MatrixXd J(values(), inputs());
    for (int j = 0; j < inputs(); ++j) {
      Eigen::VectorXd up = u;
      double h = 1e-2;
      // step inwards at an upper bound, so that clamping does not zero the column
      if (std::exp(u[j] + h) > pb_.parameters[j].upper) h = -h;
      up[j] += h;
      J.col(j) = ((*this)(up)-f0) / h;
    }
    return J;
  }

 private:
  void fill_residuals(const RecordingAnalysis& a, Eigen::VectorXd& r) const {
    if (a.filling.x.size() >= 2) {
      const PiecewiseLinear s(a.filling.x, a.filling.y);
      for (std::size_t i = 0; i < grid_.size(); ++i) {
        const double e = s(grid_[i]) - measured_[i];
        r[i] = std::isfinite(e) ? e : kFailedResidual;
      }
    }
    if (flow_grid_.empty()) return;
    const auto v = voiding_curves(a.recording, a.ics);
    const std::size_t n = grid_.size();
    const PiecewiseLinear q(v.flow_ml_s.x, v.flow_ml_s.y);
    for (std::size_t i = 0; i < flow_grid_.size(); ++i) {
      const double e = (q.empty() ? 0.0 : q(flow_grid_[i])) - measured_[n + i];
      r[n + i] = std::isfinite(e) ? e : kFailedResidual;
    }
  }

  struct Less {
    bool operator()(const std::vector<double>& a, const std::vector<double>& b) const {
      return a < b;
    }
  };
  const CalibrationProblem& pb_;
  std::vector<double> grid_, flow_grid_, measured_;
  std::map<std::vector<double>, Eigen::VectorXd, Less> cache_;
  int simulations_ = 0;
};

// Eigen's LM functor interface over Residuals.
struct LmFunctor {
  using Scalar = double;
  Residuals& residuals;
  int operator()(const Eigen::VectorXd& u, Eigen::VectorXd& f) const {
    f = residuals(u);
    return 0;
  }
  int df(const Eigen::VectorXd& u, Eigen::MatrixXd& J) const {
    J = residuals.jacobian(u);
    return 0;
  }
  int inputs() const { return residuals.inputs(); }
  int values() const { return residuals.values(); }
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

ParameterSpec parameter_spec(const std::string& name) {
  static const std::vector<ParameterSpec> all = {
      {"mu", "kPa", 5.0, 0.1, 100.0, false},       {"k", "kPa", 10.0, 0.1, 1e4, false},
      {"beta", "-", 0.15, 1e-3, 50.0, false},      {"tau", "s", 1e-4, 1e-6, 1e3, false},
      {"k1", "Pa", 10.0, 1e-2, 1e5, false},        {"k2", "-", 1.0, 1e-2, 100.0, false},
      {"r1", "cmH2O s/ml", 0.2, 1e-4, 20.0, true}, {"r2", "cmH2O s2/ml2", 0.05, 1e-5, 5.0, true},
      {"p_open", "cmH2O", 20.0, 0.5, 150.0, true},
  };
  for (const auto& s : all)
    if (s.name == name) return s;
  usage_error("--calibrate: unknown parameter \"" + name + "\"",
              "choose from mu, k, beta, tau, k1, k2, r1, r2, p_open");
}

CalibrationResult calibrate(const CalibrationProblem& pb) {
  const auto start = std::chrono::steady_clock::now();
  Residuals residuals(pb);
  if (residuals.filling_points() < 2)
    usage_error("--calibrate: the measured filling curve and the fit volumes do not overlap");
  Eigen::VectorXd u(pb.parameters.size());
  for (std::size_t j = 0; j < pb.parameters.size(); ++j)
    u[j] = std::log(
        std::clamp(pb.parameters[j].initial, pb.parameters[j].lower, pb.parameters[j].upper));

  LmFunctor functor{residuals};
  Eigen::LevenbergMarquardt<LmFunctor> lm(functor);
  lm.parameters.maxfev = std::max(2, pb.max_simulations / static_cast<int>(u.size() + 1));
  lm.parameters.xtol = 1e-3;  // 0.1 % of the parameters
  lm.parameters.ftol = 1e-4;
  const auto status = lm.minimize(u);

  CalibrationResult out;
  out.status = status_text(status);
  out.iterations = static_cast<int>(lm.iter);
  const Eigen::VectorXd r = residuals(u, &out.fitted_filling);
  const Eigen::MatrixXd J = residuals.jacobian(u);
  const std::vector<double> p = residuals.parameters(u);
  const int n = residuals.values(), m = static_cast<int>(u.size());
  const double sigma2 = r.squaredNorm() / std::max(1, n - m);
  const Eigen::MatrixXd cov =
      sigma2 * (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse();
  for (int j = 0; j < m; ++j) {
    FittedParameter f;
    const auto& s = pb.parameters[j];
    f.name = s.name;
    f.unit = s.unit;
    f.initial = s.initial;
    f.lower = s.lower;
    f.upper = s.upper;
    f.value = p[j];
    f.standard_error = p[j] * std::sqrt(std::max(0.0, cov(j, j)));
    f.ci_low = f.value - 1.96 * f.standard_error;
    f.ci_high = f.value + 1.96 * f.standard_error;
    out.parameters.push_back(f);
  }
  const Eigen::VectorXd rf = r.head(residuals.filling_points());
  out.rmse_cmh2o = std::sqrt(rf.squaredNorm() / rf.size());
  out.max_abs_error_cmh2o = rf.cwiseAbs().maxCoeff();
  out.volume_lo_ml = pb.volume_lo_ml;
  out.volume_hi_ml = pb.volume_hi_ml;
  out.simulations = residuals.simulations();
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace vesica::compare
