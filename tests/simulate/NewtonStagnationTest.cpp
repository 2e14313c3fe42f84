// The Newton loop's stagnation test (docs/physics.md §3.3), on a system whose relative
// residuals are scripted, so that what the loop does is checked against a table worked by
// hand: with a window of 8 and a factor of 1/2 a residual that stops falling ends the solve
// 8 iterations after its plateau began; one that keeps halving within every 8 iterations,
// however slowly, converges; and with the test off (the default) the plateau runs the
// whole budget.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "solver/NewtonLoop.h"

using namespace vesica::simulate;

namespace {

// One unknown; the k-th evaluation's residual is script[k] (the last one repeated).
class ScriptedSystem : public NewtonSystem {
 public:
  explicit ScriptedSystem(std::vector<double> script) : script_(std::move(script)) {
    K_.resize(1, 1);
    K_.insert(0, 0) = 1.0;
  }
  std::size_t unknown_count() const override { return 1; }
  bool increment_converged(int, double) const override { return true; }
  bool tests_residual() const override { return true; }
  void evaluate() override { ++evaluations_; }
  ResidualCheck check_residual() override {
    const std::size_t k = std::min<std::size_t>(evaluations_ - 1, script_.size() - 1);
    ResidualCheck c;
    c.norm = script_[k];
    c.converged = c.norm <= kTolerance;
    return c;
  }
  Eigen::SparseMatrix<double>& tangent() override { return K_; }
  bool solve_increment(bool, std::string&) override { return true; }
  double increment_move() const override { return 1.0; }
  void apply_increment() override {}

  static constexpr double kTolerance = 1e-9;

 private:
  std::vector<double> script_;
  std::size_t evaluations_ = 0;
  Eigen::SparseMatrix<double> K_;
};

// The loop's solve of the scripted system with the stagnation test's factor (0: off), a
// window of 8 and no line search.
NewtonReport solve_scripted(std::vector<double> script, double factor, int max_iterations) {
  NewtonOptions o;
  o.max_iterations = max_iterations;
  o.stagnation_window = 8;
  o.stagnation_factor = factor;
  o.line_search.enabled = false;
  ScriptedSystem system(std::move(script));
  return NewtonLoop(o).solve(system);
}

// 1e-2, 1e-3, then 1e-4 for ever.
std::vector<double> plateau() {
  std::vector<double> r = {1e-2, 1e-3};
  r.resize(60, 1e-4);
  return r;
}

}  // namespace

TEST(NewtonStagnation, AResidualOnAPlateauEndsTheSolveEightIterationsIntoIt) {
  const NewtonReport r = solve_scripted(plateau(), 0.5, 25);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.failure, "Newton iteration stagnates");
  // The plateau starts at the residual of iteration 2; iterations 3 to 10 find nothing
  // below it, let alone half of it: the loop stops at iteration 10, not at the budget's 25.
  EXPECT_EQ(r.iterations, 10);
  EXPECT_EQ(r.residual_norms.size(), 11u);
}

TEST(NewtonStagnation, ASlowButSteadyResidualStillConverges) {
  // Falling by 0.9 an iteration (0.9⁸ = 0.43, below one half in every window of 8) from
  // 1e-2 to the tolerance 1e-9: 153 iterations, first below at k = ⌈ln(1e-7)/ln(0.9)⌉.
  std::vector<double> script;
  for (int k = 0; k < 200; ++k) script.push_back(1e-2 * std::pow(0.9, k));
  const NewtonReport r = solve_scripted(script, 0.5, 200);
  EXPECT_TRUE(r.converged) << r.failure;
  EXPECT_EQ(r.iterations, static_cast<int>(std::ceil(std::log(1e-7) / std::log(0.9))));
}

TEST(NewtonStagnation, WithTheTestOffAPlateauRunsTheWholeBudget) {
  const NewtonReport r = solve_scripted(plateau(), 0.0, 25);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.failure, "no convergence in 25 iterations");
  EXPECT_EQ(NewtonOptions{}.stagnation_factor, 0.0);  // off unless a caller cuts back
}
