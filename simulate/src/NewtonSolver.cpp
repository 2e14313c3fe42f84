#include "vesica/simulate/NewtonSolver.h"

#include <cmath>
#include <stdexcept>

#include "vesica/core/Log.h"
#include "vesica/simulate/LinearSolver.h"

namespace vesica::simulate {

struct NewtonSolver::Factorization {
  LinearSolver solver;
  // The factorization holds a tangent of the last converged state (or of this solve):
  // see the reuse rule in solve().
  bool reusable = false;
};

NewtonSolver::NewtonSolver(MembraneProblem& problem, NewtonOptions options)
    : problem_(problem), options_(options), lu_(std::make_shared<Factorization>()) {
  Eigen::AlignedBox3d box;
  for (const auto& p : problem.wall().nodes) box.extend(p);
  size_ = box.diagonal().norm();
}

NewtonReport NewtonSolver::solve(const CavityEquation& cavity, WallLoads& loads,
                                 std::vector<Eigen::Vector3d>& x) {
  NewtonReport report;
  double last_increment = INFINITY;
  bool reusable = lu_->reusable;
  lu_->reusable = false;  // until this solve converges
  for (int it = 0; it <= options_.max_iterations; ++it) {
    try {
      problem_.assemble(x, loads, true, assembly_);
    } catch (const std::runtime_error& e) {
      report.failure = e.what();
      return report;
    }
    const WallAssembly& A = assembly_;
    double dq = 0.0, c = 0.0, dc_dp = 0.0;
    if (cavity.volume_control) {
      c = A.volume - cavity.volume_base_m3;
      if (cavity.outflow) c += cavity.outflow(loads.inside.p0, dq);
      dc_dp = dq;
    } else {
      c = loads.inside.p0 - cavity.pressure_pa;
      dc_dp = 1.0;
    }
    const double r_rel = A.residual.norm() / std::max(A.force_scale, 1e-300);
    // Near zero load the relative test is meaningless: a residual that would move the
    // model by 1e-13 of its size through the stiffest dof counts as zero.
    const double floor =
        1e-13 * size_ * (A.K.nonZeros() ? A.K.diagonal().cwiseAbs().maxCoeff() : 0.0);
    const bool r_ok = A.residual.norm() <= options_.residual_tolerance * A.force_scale ||
                      A.residual.norm() <= floor;
    const double c_scale = cavity.volume_control ? std::abs(A.volume) : 1.0;
    const bool c_ok =
        std::abs(c) <= options_.volume_tolerance * c_scale || (!cavity.volume_control && c == 0.0);
    report.residual_norms.push_back(r_rel);
    vesica::log()->debug("newton {}: |r|/|f| = {:.3e}, |r| = {:.3e} N, c = {:.3e}, p0 = {:.6g} Pa",
                         it, r_rel, A.residual.norm(), c, loads.inside.p0);
    report.iterations = it;
    if (!std::isfinite(r_rel) || !std::isfinite(c)) {
      report.failure = "residual is not finite";
      return report;
    }
    if (r_ok && c_ok && (it > 0 ? last_increment <= options_.increment_tolerance * size_ : true)) {
      report.converged = true;
      lu_->reusable = reusable;
      return report;
    }
    if (it == options_.max_iterations) break;
    if (it >= 3 && r_rel > 1e3 * report.residual_norms[1] && r_rel > 1e-3) {
      report.failure = "Newton iteration diverges";
      return report;
    }
    if (problem_.free_dof_count() == 0) break;
    // Modified-Newton reuse: with the wall already in equilibrium (r_ok) only the cavity
    // equation (first iteration of a step) or the increment test (last one) is unmet, the
    // correction is small and the last tangent, from this solve or the converged state of
    // the previous one, serves it as well as a new factorization would. Every other
    // iteration factorizes its own tangent, which keeps the convergence quadratic.
    if (!(r_ok && reusable)) {
      if (!lu_->solver.factorize(A.K)) {
        report.failure = "singular tangent matrix";
        return report;
      }
      reusable = true;
    }
    // u_p is needed whenever p0 changes: always under volume control, under pressure
    // control only until p0 equals the prescribed pressure.
    const bool need_u_p = cavity.volume_control || c != 0.0;
    Eigen::MatrixXd B(A.residual.size(), need_u_p ? 2 : 1);
    B.col(0) = -A.residual;
    if (need_u_p) B.col(1) = -A.dr_dp0;
    const Eigen::MatrixXd U = lu_->solver.solve(B);
    const auto u_r = U.col(0);
    const Eigen::VectorXd u_p = need_u_p ? Eigen::VectorXd(U.col(1)) : Eigen::VectorXd();
    double dp = 0.0;
    if (cavity.volume_control) {
      const double denom = A.dV_du.dot(u_p) + dc_dp;
      if (denom == 0.0) {
        report.failure = "singular cavity equation";
        return report;
      }
      dp = (-c - A.dV_du.dot(u_r)) / denom;
    } else {
      dp = -c;
    }
    const Eigen::VectorXd du = need_u_p ? Eigen::VectorXd(u_r + dp * u_p) : Eigen::VectorXd(u_r);
    if (!du.allFinite()) {
      report.failure = "increment is not finite";
      return report;
    }
    problem_.apply_increment(du, x);
    loads.inside.p0 += dp;
    last_increment = du.size() ? du.cwiseAbs().maxCoeff() : 0.0;
  }
  report.failure = "no convergence in " + std::to_string(options_.max_iterations) + " iterations";
  return report;
}

}  // namespace vesica::simulate
