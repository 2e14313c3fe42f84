#pragma once
// One model's residuals against the targets as a function of u = ln p (docs/physics.md §9):
// each p clamped to its bounds when simulated; runs cached by their values (the solver asks
// for the same point for the value and the Jacobian), counted, and limited by a budget;
// failed runs counted and their reasons kept. An additive offset (the output space mapping
// of the second stage) can be laid on the residuals the solver sees.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "vesica/compare/calibration/CalibrationTargets.h"
#include "vesica/compare/calibration/FitParameter.h"
#include "vesica/compare/calibration/ModelRun.h"

namespace vesica::compare {

class FitObjective {
 public:
  struct Point {
    ModelRun run;
    Evaluation evaluation;
    double cost = 0;  // squared norm of the scaled residuals (penalty included)
  };

  FitObjective(const std::vector<FitParameter>& parameters, const CalibrationTargets& targets,
               ModelSimulator simulate, int budget);

  std::vector<double> values(const Eigen::VectorXd& u) const;  // p within the bounds
  Eigen::VectorXd u_of(const std::vector<double>& values) const;

  // The run at u; nullptr when it is not cached and the budget is spent.
  const Point* at(const Eigen::VectorXd& u);
  // Residuals the solver sees at u (with the offset); nullopt when the budget is spent.
  std::optional<Eigen::VectorXd> residuals(const Eigen::VectorXd& u);
  // Forward differences of the residuals in u, step 0.01 (1 % of p: the simulations'
  // Newton tolerance makes smaller steps noisy), inwards at an upper bound, the other way
  // when the step's run fails; a row compared at only one of the two runs has no
  // derivative (0). A column whose both steps fail is 0 and named in `notes`.
  std::optional<Eigen::MatrixXd> jacobian(const Eigen::VectorXd& u,
                                          std::vector<std::string>* notes = nullptr);

  void set_offset(const Eigen::VectorXd& offset) { offset_ = offset; }
  void clear_offset() { offset_.resize(0); }
  void set_budget(int budget) { budget_ = budget; }

  int simulations() const { return simulations_; }
  int failures() const { return failures_; }
  int budget() const { return budget_; }
  bool spent() const { return simulations_ >= budget_; }
  int inputs() const { return static_cast<int>(parameters_.size()); }
  int values_count() const { return static_cast<int>(targets_.size()); }
  const CalibrationTargets& targets() const { return targets_; }
  const std::vector<FitParameter>& parameters() const { return parameters_; }
  // Why the failed runs failed, each reason once, with its count.
  std::vector<std::string> failure_summary() const;

 private:
  const std::vector<FitParameter>& parameters_;
  const CalibrationTargets& targets_;
  ModelSimulator simulate_;
  int budget_;
  int simulations_ = 0, failures_ = 0;
  Eigen::VectorXd offset_;
  std::map<std::vector<double>, Point> cache_;
  std::map<std::string, int> failure_reasons_;
};

}  // namespace vesica::compare
