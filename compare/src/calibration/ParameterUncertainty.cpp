#include "vesica/compare/calibration/ParameterUncertainty.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace vesica::compare {
namespace {

constexpr double kZ95 = 1.96;
constexpr double kRoundingVariance = 1.0 / 12.0;  // readings rounded to whole scale units
constexpr double kRankTolerance = 1e-8;           // of the largest singular value
constexpr double kMinSensitivity = 1e-4;          // scaled residual RMS for +10 %
constexpr double kMaxIntervalFactor = 10.0;       // identifiable: interval within a factor 10
constexpr double kStrongCorrelation = 0.95;
const double kInf = std::numeric_limits<double>::infinity();

std::string fixed(double v, int digits) {
  std::ostringstream o;
  o.precision(digits);
  o << v;
  return o.str();
}

// Covariance of u from the SVD; +inf on the diagonal of parameters in an undetermined
// direction (and their off-diagonal entries left at 0).
Eigen::MatrixXd covariance(const Eigen::MatrixXd& J, double sigma2, std::vector<bool>& determined) {
  const Eigen::Index m = J.cols();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
  const Eigen::VectorXd& s = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixV();
  determined.assign(static_cast<std::size_t>(m), true);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(m, m);
  const double smax = s.size() ? s[0] : 0.0;
  for (Eigen::Index k = 0; k < s.size(); ++k) {
    if (smax > 0 && s[k] > kRankTolerance * smax) {
      cov += sigma2 / (s[k] * s[k]) * V.col(k) * V.col(k).transpose();
      continue;
    }
    for (Eigen::Index j = 0; j < m; ++j)
      if (std::abs(V(j, k)) > 1e-3) determined[static_cast<std::size_t>(j)] = false;
  }
  for (Eigen::Index j = 0; j < m; ++j)
    if (!determined[static_cast<std::size_t>(j)]) cov(j, j) = kInf;
  return cov;
}

void mark_bound(const FitParameter& p, double value, ParameterUncertainty& u) {
  const double tol = 5e-3;  // in ln p
  if (std::log(value) <= std::log(p.lower) + tol) {
    u.at_bound = true;
    u.reason += (u.reason.empty() ? "" : "; ") + std::string("at its lower bound");
  } else if (std::log(value) >= std::log(p.upper) - tol) {
    u.at_bound = true;
    u.reason += (u.reason.empty() ? "" : "; ") + std::string("at its upper bound");
  }
}

}  // namespace

std::vector<ParameterUncertainty> parameter_uncertainty(const Eigen::MatrixXd& J,
                                                        const Eigen::VectorXd& r,
                                                        const std::vector<FitParameter>& params,
                                                        const std::vector<double>& values) {
  const auto m = static_cast<Eigen::Index>(params.size());
  const Eigen::Index n = J.rows();
  std::vector<ParameterUncertainty> out(params.size());
  for (Eigen::Index j = 0; j < m; ++j) {
    auto& u = out[static_cast<std::size_t>(j)];
    u.ci_low = params[j].lower;
    u.ci_high = params[j].upper;
    u.standard_error = kInf;
    if (n > 0) u.sensitivity = std::log(1.1) * J.col(j).norm() / std::sqrt(double(n));
  }
  if (n <= m) {
    for (auto& u : out)
      u.reason =
          "fewer readings (" + std::to_string(n) + ") than parameters (" + std::to_string(m) + ")";
    return out;
  }
  const double sigma2 = std::max(r.squaredNorm() / double(n - m), kRoundingVariance);
  std::vector<bool> determined;
  const Eigen::MatrixXd cov = covariance(J, sigma2, determined);
  for (Eigen::Index j = 0; j < m; ++j) {
    const auto sj = static_cast<std::size_t>(j);
    auto& u = out[sj];
    const FitParameter& p = params[sj];
    const double v = values[sj];
    if (u.sensitivity < kMinSensitivity) {
      u.reason = "the data do not depend on it (a 10 % change moves them by " +
                 fixed(u.sensitivity, 2) + " of their scale)";
    } else if (!determined[sj]) {
      u.reason = "only a combination with other parameters is determined";
    } else {
      const double se = std::sqrt(std::max(0.0, cov(j, j)));
      u.standard_error = v * se;
      u.ci_low = std::max(p.lower, v * std::exp(-kZ95 * se));
      u.ci_high = std::min(p.upper, v * std::exp(kZ95 * se));
      const double factor = std::exp(2 * kZ95 * se);
      u.identifiable = factor < kMaxIntervalFactor;
      if (!u.identifiable)
        u.reason = "the data allow a factor of " +
                   (factor > 1e3 ? std::string("more than 1000") : fixed(factor, 3)) +
                   " (95 % interval)";
      for (Eigen::Index k = 0; k < m; ++k) {
        if (k == j || !determined[static_cast<std::size_t>(k)]) continue;
        const double c = cov(j, k) / std::sqrt(cov(j, j) * cov(k, k));
        if (std::abs(c) > kStrongCorrelation)
          u.reason += (u.reason.empty() ? "" : "; ") + std::string("correlated with ") +
                      params[static_cast<std::size_t>(k)].name + " (r = " + fixed(c, 3) + ")";
      }
    }
    mark_bound(p, v, u);
  }
  return out;
}

}  // namespace vesica::compare
