#include "calibration/FitObjective.h"

#include <algorithm>
#include <cmath>

namespace vesica::compare {
namespace {

constexpr double kLogStep = 1e-2;

// The failure text without its numbers, so that runs failing the same way count together.
std::string failure_kind(const std::string& failure) {
  const auto colon = failure.rfind(": ");
  return colon == std::string::npos ? failure : failure.substr(colon + 2);
}

}  // namespace

FitObjective::FitObjective(const std::vector<FitParameter>& parameters,
                           const CalibrationTargets& targets, ModelSimulator simulate, int budget)
    : parameters_(parameters), targets_(targets), simulate_(std::move(simulate)), budget_(budget) {}

std::vector<double> FitObjective::values(const Eigen::VectorXd& u) const {
  std::vector<double> p(static_cast<std::size_t>(u.size()));
  for (Eigen::Index j = 0; j < u.size(); ++j) {
    const auto& s = parameters_[static_cast<std::size_t>(j)];
    p[static_cast<std::size_t>(j)] = std::clamp(std::exp(u[j]), s.lower, s.upper);
  }
  return p;
}

Eigen::VectorXd FitObjective::u_of(const std::vector<double>& values) const {
  Eigen::VectorXd u(static_cast<Eigen::Index>(values.size()));
  for (std::size_t j = 0; j < values.size(); ++j)
    u[static_cast<Eigen::Index>(j)] =
        std::log(std::clamp(values[j], parameters_[j].lower, parameters_[j].upper));
  return u;
}

const FitObjective::Point* FitObjective::at(const Eigen::VectorXd& u) {
  const std::vector<double> p = values(u);
  const auto hit = cache_.find(p);
  if (hit != cache_.end()) return &hit->second;
  if (spent()) return nullptr;
  ++simulations_;
  Point point;
  point.run = simulate_(p);
  point.evaluation = evaluate(targets_, point.run);
  point.cost = point.evaluation.residuals.squaredNorm();
  if (point.evaluation.failed) {
    ++failures_;
    ++failure_reasons_[failure_kind(point.evaluation.failure)];
  }
  return &cache_.emplace(p, std::move(point)).first->second;
}

std::optional<Eigen::VectorXd> FitObjective::residuals(const Eigen::VectorXd& u) {
  const Point* point = at(u);
  if (!point) return std::nullopt;
  if (offset_.size() == 0) return point->evaluation.residuals;
  return Eigen::VectorXd(point->evaluation.residuals + offset_);
}

std::optional<Eigen::MatrixXd> FitObjective::jacobian(const Eigen::VectorXd& u,
                                                      std::vector<std::string>* notes) {
  const Point* base = at(u);
  if (!base) return std::nullopt;
  const Evaluation e0 = base->evaluation;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(e0.residuals.size(), u.size());
  for (Eigen::Index j = 0; j < u.size(); ++j) {
    const auto& s = parameters_[static_cast<std::size_t>(j)];
    const double first = std::exp(u[j] + kLogStep) > s.upper ? -kLogStep : kLogStep;
    double h = first;
    const Point* step = nullptr;
    for (double trial : {first, -first}) {
      Eigen::VectorXd up = u;
      up[j] += trial;
      step = at(up);
      if (!step) return std::nullopt;
      h = trial;
      if (!step->evaluation.failed) break;
    }
    if (step->evaluation.failed || e0.failed) {
      if (notes) notes->push_back("no derivative for " + s.name + ": " + step->evaluation.failure);
      continue;
    }
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      const auto si = static_cast<std::size_t>(i);
      if (e0.compared[si] && step->evaluation.compared[si])
        J(i, j) = (step->evaluation.residuals[i] - e0.residuals[i]) / h;
    }
  }
  return J;
}

std::vector<std::string> FitObjective::failure_summary() const {
  std::vector<std::string> out;
  for (const auto& [reason, count] : failure_reasons_)
    out.push_back(std::to_string(count) + " × " + reason);
  return out;
}

}  // namespace vesica::compare
