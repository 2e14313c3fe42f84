#include "fluid/FluidNewton.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "solver/LinearSolver.h"
#include "solver/NewtonLoop.h"
#include "vesica/core/Log.h"

namespace vesica::simulate::fluid {

// With UMFPACK's iterative refinement: the convergence test asks velocity increments down
// to 1e-12 m/s of a fluid at rest, below what an unrefined solve resolves.
struct FluidNewton::Factorization {
  LinearSolver lu{LinearSolver::Symmetry::Unsymmetric, LinearSolver::Refinement::Iterative};
};

namespace {

// Largest magnitude of the velocity (fields 0-2) or pressure (field 3 and the outlet
// pressure after the node dofs) entries.
double field_max(const Eigen::VectorXd& v, int node_dofs, bool pressure) {
  double m = 0.0;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const bool is_pressure = i >= node_dofs || i % kDofsPerNode == 3;
    if (is_pressure == pressure) m = std::max(m, std::abs(v[i]));
  }
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// The urine state as the Newton loop's iterate.
class FluidNewton::System final : public NewtonSystem {
 public:
  System(const FluidProblem& problem, const FluidNewtonOptions& options, LinearSolver& lu,
         const Eigen::VectorXd& state_old, double inverse_dt, Eigen::VectorXd& state,
         const AleFrame* frame, FluidNewtonReport& report)
      : problem_(problem),
        options_(options),
        lu_(lu),
        state_old_(state_old),
        inverse_dt_(inverse_dt),
        state_(state),
        frame_(frame),
        report_(report) {}

  std::size_t unknown_count() const override {
    return static_cast<std::size_t>(problem_.dof_count());
  }
  bool increment_converged(int increments, double /*no wall*/) const override {
    return increments > 0 && converged_;
  }
  bool tests_residual() const override { return false; }

  void evaluate() override {
    const auto t0 = std::chrono::steady_clock::now();
    problem_.assemble(state_, state_old_, inverse_dt_, residual_, &jacobian_, frame_);
    report_.assembly_seconds += seconds_since(t0);
  }

  Eigen::SparseMatrix<double>& tangent() override { return jacobian_; }

  bool solve_increment(bool /*reuse: never*/, std::string& failure) override {
    const auto t0 = std::chrono::steady_clock::now();
    if (!lu_.factorize(jacobian_)) {
      failure = "singular fluid Jacobian";
      return false;
    }
    delta_ = -lu_.solve(residual_).col(0);
    if (!delta_.allFinite()) {
      failure = "fluid Newton increment is not finite";
      return false;
    }
    report_.solve_seconds += seconds_since(t0);
    return true;
  }

  double increment_move() const override { return 0.0; }

  void apply_increment() override {
    state_ += delta_;
    const int n = problem_.node_dof_count();
    const double du = field_max(delta_, n, false), dp = field_max(delta_, n, true);
    const double u_scale = field_max(state_, n, false), p_scale = field_max(state_, n, true);
    report_.increments.push_back(du / std::max(u_scale, options_.velocity_floor));
    vesica::log()->debug("fluid newton: |du| = {:.3e} m/s, |dp| = {:.3e} Pa", du, dp);
    const bool u_ok = du <= options_.increment_tolerance * u_scale || du <= options_.velocity_floor;
    const bool p_ok = dp <= options_.increment_tolerance * p_scale || dp <= options_.pressure_floor;
    converged_ = u_ok && p_ok;
  }

 private:
  const FluidProblem& problem_;
  const FluidNewtonOptions& options_;
  LinearSolver& lu_;
  const Eigen::VectorXd& state_old_;
  const double inverse_dt_;
  Eigen::VectorXd& state_;
  const AleFrame* frame_;
  FluidNewtonReport& report_;
  Eigen::VectorXd residual_, delta_;
  Eigen::SparseMatrix<double> jacobian_;
  bool converged_ = false;  // the last increment was small in every field
};

FluidNewton::FluidNewton(const FluidProblem& problem, FluidNewtonOptions options)
    : problem_(problem), options_(options), lu_(std::make_unique<Factorization>()) {}

FluidNewton::~FluidNewton() = default;

FluidNewtonReport FluidNewton::solve(const Eigen::VectorXd& state_old, double inverse_dt,
                                     Eigen::VectorXd& state, const AleFrame* frame) {
  FluidNewtonReport report;
  problem_.apply_constraints(state);
  NewtonOptions loop_options;
  loop_options.max_iterations = options_.max_iterations;
  loop_options.regularized_iterations_extend_budget = false;
  loop_options.divergence_ratio = 0.0;
  loop_options.line_search.enabled = false;
  NewtonLoop loop(loop_options);
  System system(problem_, options_, lu_->lu, state_old, inverse_dt, state, frame, report);
  const NewtonReport r = loop.solve(system);
  report.converged = r.converged;
  report.iterations = r.iterations;
  report.failure = r.failure;
  return report;
}

}  // namespace vesica::simulate::fluid
