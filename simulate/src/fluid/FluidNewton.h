#pragma once
// Newton iteration for one (steady or backward-Euler) step of FluidProblem: the urine alone
// in a given (fixed or moving) mesh. A system of the one Newton loop (NewtonLoop.h), without
// wall (so no foundation) and without line search; every iteration factorizes its own
// Jacobian (LinearSolver's LU with iterative refinement, the symbolic analysis kept, since
// the pattern is fixed per mesh). Converged when the last increment is small in every field.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "fluid/FluidProblem.h"

namespace vesica::simulate::fluid {

struct FluidNewtonOptions {
  int max_iterations = 25;
  double increment_tolerance = 1e-9;  // max |Δ| relative to max |U|, per field
  double velocity_floor = 1e-12;      // m/s: increments below this count as zero
  double pressure_floor = 1e-9;       // Pa
};

struct FluidNewtonReport {
  bool converged = false;
  int iterations = 0;
  std::vector<double> increments;  // relative velocity increment per iteration
  std::string failure;
  double assembly_seconds = 0.0;  // wall-clock, summed over iterations
  double solve_seconds = 0.0;     // LU factorization and solve
};

class FluidNewton {
 public:
  explicit FluidNewton(const FluidProblem& problem, FluidNewtonOptions options = {});
  ~FluidNewton();

  // Updates state in place; inverse_dt = 0 for steady flow; frame: the moved mesh (ALE),
  // null for the fixed one.
  FluidNewtonReport solve(const Eigen::VectorXd& state_old, double inverse_dt,
                          Eigen::VectorXd& state, const AleFrame* frame = nullptr);

 private:
  class System;
  struct Factorization;
  const FluidProblem& problem_;
  FluidNewtonOptions options_;
  std::unique_ptr<Factorization> lu_;
};

}  // namespace vesica::simulate::fluid
