#include "fluid/FluidNewton.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include <Eigen/UmfPackSupport>

#include "vesica/core/Log.h"

namespace vesica::simulate::fluid {

struct FluidNewton::Factorization {
  Eigen::UmfPackLU<Eigen::SparseMatrix<double>> lu;
  bool analyzed = false;
};

FluidNewton::FluidNewton(const FluidProblem& problem, FluidNewtonOptions options)
    : problem_(problem), options_(options), lu_(std::make_unique<Factorization>()) {}

FluidNewton::~FluidNewton() = default;

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

}  // namespace

FluidNewtonReport FluidNewton::solve(const Eigen::VectorXd& state_old, double inverse_dt,
                                     Eigen::VectorXd& state, const AleFrame* frame) {
  FluidNewtonReport report;
  Eigen::VectorXd residual;
  Eigen::SparseMatrix<double> jacobian;
  problem_.apply_constraints(state);
  for (int it = 1; it <= options_.max_iterations; ++it) {
    const auto t0 = std::chrono::steady_clock::now();
    try {
      problem_.assemble(state, state_old, inverse_dt, residual, &jacobian, frame);
    } catch (const std::runtime_error& e) {
      report.failure = e.what();
      return report;
    }
    const auto t1 = std::chrono::steady_clock::now();
    report.assembly_seconds += std::chrono::duration<double>(t1 - t0).count();
    if (!lu_->analyzed) {
      lu_->lu.analyzePattern(jacobian);
      lu_->analyzed = true;
    }
    lu_->lu.factorize(jacobian);
    if (lu_->lu.info() != Eigen::Success) {
      report.failure = "singular fluid Jacobian";
      return report;
    }
    const Eigen::VectorXd delta = -lu_->lu.solve(residual);
    if (!delta.allFinite()) {
      report.failure = "fluid Newton increment is not finite";
      return report;
    }
    report.solve_seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
    state += delta;
    report.iterations = it;
    const int n = problem_.node_dof_count();
    const double du = field_max(delta, n, false), dp = field_max(delta, n, true);
    const double u_scale = field_max(state, n, false), p_scale = field_max(state, n, true);
    const double rel_u = du / std::max(u_scale, options_.velocity_floor);
    report.increments.push_back(rel_u);
    vesica::log()->debug("fluid newton {}: |du| = {:.3e} m/s, |dp| = {:.3e} Pa", it, du, dp);
    const bool u_ok = du <= options_.increment_tolerance * u_scale || du <= options_.velocity_floor;
    const bool p_ok = dp <= options_.increment_tolerance * p_scale || dp <= options_.pressure_floor;
    if (u_ok && p_ok) {
      report.converged = true;
      return report;
    }
  }
  report.failure =
      "fluid Newton did not converge in " + std::to_string(options_.max_iterations) + " iterations";
  return report;
}

}  // namespace vesica::simulate::fluid
