#include "NewtonSolver.h"

#include <cmath>
#include <stdexcept>

#include "LinearSolver.h"
#include "vesica/core/Log.h"

namespace vesica::simulate {

namespace {

// The cavity equation's residual c at pressure p0 and its derivative dc/dp0: under volume
// control V - V_base + θ Δt Q_out(p0), under pressure control p0 - p.
double cavity_residual(const CavityEquation& cavity, const WallAssembly& A, double p0,
                       double* dc_dp = nullptr) {
  double c = 0.0, d = 1.0;
  if (cavity.volume_control) {
    d = 0.0;
    c = A.volume - cavity.volume_base_m3;
    if (cavity.outflow) c += cavity.outflow(p0, d);
  } else {
    c = p0 - cavity.pressure_pa;
  }
  if (dc_dp) *dc_dp = d;
  return c;
}

// The least wall move that meets the cavity equation: under volume control the volume
// must change by -c, and the shortest increment doing so, du = -c g / |g|², moves its
// farthest dof by |c| |g|∞ / |g|². That much motion is demanded by the load, not a
// sign of a slack mode, so the move limit of a Newton step adds it: without it a filling
// step of a refined wall (edges shorter than the wall's uniform outward move of the step)
// was taken for a runaway step and crawled on the foundation (16,928-triangle sphere: 28
// iterations, 22 of them regularized, for 7.5 ml at 130 ml; filling reached 205 ml after
// 151 s, and 350 ml after 12 s with this term).
double cavity_move(const CavityEquation& cavity, const Eigen::VectorXd& g, double c) {
  if (!cavity.volume_control || g.size() == 0) return 0.0;
  const double g2 = g.squaredNorm();
  return g2 > 0.0 ? std::abs(c) * g.cwiseAbs().maxCoeff() / g2 : 0.0;
}

}  // namespace

struct NewtonSolver::Factorization {
  LinearSolver solver;
  // The factorization holds a tangent of the last converged state (or of this solve):
  // see the reuse rule in solve().
  bool reusable = false;
};

NewtonSolver::NewtonSolver(MembraneProblem& problem, NewtonOptions options)
    : problem_(problem), options_(options), lu_(std::make_shared<Factorization>()) {
  const WallModel& wall = problem.wall();
  Eigen::AlignedBox3d box;
  for (const auto& p : wall.nodes) box.extend(p);
  size_ = box.diagonal().norm();
  double edges = 0.0;
  for (const auto& t : wall.triangles)
    for (int k = 0; k < 3; ++k) edges += (wall.nodes[t[(k + 1) % 3]] - wall.nodes[t[k]]).norm();
  mean_edge_ = wall.triangles.empty() ? size_ : edges / (3.0 * wall.triangle_count());
  foundation_area_.resize(static_cast<Eigen::Index>(problem.free_dof_count()));
  for (std::size_t g = 0; g < problem.dof_map().size(); ++g)
    if (problem.dof_map()[g] >= 0)
      foundation_area_(problem.dof_map()[g]) = problem.node_areas()[g / 3];
}

bool NewtonSolver::bordered_step(const CavityEquation& cavity, double c, double dc_dp, double eta,
                                 bool reuse, Eigen::VectorXd& du, double& dp,
                                 std::string& failure) {
  WallAssembly& A = assembly_;
  const double added = eta - eta_in_K_;
  if (added != 0.0) {
    for (Eigen::Index d = 0; d < foundation_area_.size(); ++d)
      A.K.coeffRef(d, d) += added * foundation_area_(d);
    eta_in_K_ = eta;
  }
  if (!reuse || added != 0.0) {
    if (!lu_->solver.factorize(A.K)) {
      failure = "singular tangent matrix";
      return false;
    }
  }
  // u_p is needed whenever p0 changes: always under volume control, under pressure
  // control only until p0 equals the prescribed pressure.
  const bool need_u_p = cavity.volume_control || c != 0.0;
  Eigen::MatrixXd B(A.residual.size(), need_u_p ? 2 : 1);
  B.col(0) = -A.residual;
  if (need_u_p) B.col(1) = -A.dr_dp0;
  const Eigen::MatrixXd U = lu_->solver.solve(B);
  dp = 0.0;
  if (cavity.volume_control) {
    const double denom = A.dV_du.dot(U.col(1)) + dc_dp;
    if (denom == 0.0) {
      failure = "singular cavity equation";
      return false;
    }
    dp = (-c - A.dV_du.dot(U.col(0))) / denom;
  } else {
    dp = -c;
  }
  du = need_u_p ? Eigen::VectorXd(U.col(0) + dp * U.col(1)) : Eigen::VectorXd(U.col(0));
  if (!du.allFinite()) {
    failure = "increment is not finite";
    return false;
  }
  return true;
}

// Backtracking line search for the wrinkling wall: its elements switch between slack (no
// stiffness) and taut (full stiffness), and the full Newton step can jump across such a
// switch and back forever (a 2-cycle of the residual, 0.34 ↔ 0.97, with the cavity
// equation missed by 3e-4 V each way). The merit is the sum of the squared wall residual
// and cavity residual, each relative to its value at the start of the iteration (floored
// at what counts as small, so that a converged part may grow a little); the step is
// halved until the merit falls. The trial assembly, with its tangent, is kept as the next
// iteration's, so an accepted full step costs nothing extra.
bool NewtonSolver::line_search(const CavityEquation& cavity, WallLoads& loads,
                               const Eigen::VectorXd& du, double dp,
                               std::vector<Eigen::Vector3d>& x) {
  const double r_ref = std::max(assembly_.residual.norm(), 1e-6 * assembly_.force_scale);
  const double c_ref = std::max(std::abs(cavity_residual(cavity, assembly_, loads.inside.p0)),
                                1e-8 * std::abs(assembly_.volume));
  auto merit = [&](const WallAssembly& a, double p0) {
    const double r = a.residual.norm() / r_ref, c = cavity_residual(cavity, a, p0) / c_ref;
    return r * r + c * c;
  };
  const double merit0 = merit(assembly_, loads.inside.p0);
  const std::vector<Eigen::Vector3d> x0 = x;
  const double p0 = loads.inside.p0;
  WallAssembly trial;
  line_search_step_ = 1.0;
  for (int halving = 0;; ++halving, line_search_step_ *= 0.5) {
    x = x0;
    problem_.apply_increment(line_search_step_ * du, x);
    loads.inside.p0 = p0 + line_search_step_ * dp;
    bool ok = true;
    try {
      problem_.assemble(x, loads, true, trial);
    } catch (const std::runtime_error&) {
      ok = false;  // an inverted element: the step is too long
    }
    if ((ok && merit(trial, loads.inside.p0) < merit0) || halving == 4) {
      if (!ok) return false;  // assemble at the top of the next iteration reports it
      std::swap(assembly_, trial);
      return true;
    }
  }
}

NewtonReport NewtonSolver::solve(const CavityEquation& cavity, WallLoads& loads,
                                 std::vector<Eigen::Vector3d>& x) {
  NewtonReport report;
  double last_increment = INFINITY;
  bool reusable = lu_->reusable;
  lu_->reusable = false;  // until this solve converges
  // Regularized iterations are pseudo-time steps towards equilibrium: they extend the
  // budget, up to twice the plain Newton limit (past that a shorter step is cheaper).
  auto limit = [&] {
    return std::min(options_.max_iterations + report.regularized_iterations,
                    2 * options_.max_iterations);
  };
  bool assembled = false;  // the line search of the last iteration assembled x already
  for (int it = 0; it <= limit(); ++it) {
    if (!assembled) {
      try {
        problem_.assemble(x, loads, true, assembly_);
      } catch (const std::runtime_error& e) {
        report.failure = e.what();
        return report;
      }
    }
    assembled = false;
    const WallAssembly& A = assembly_;
    double dc_dp = 0.0;
    const double c = cavity_residual(cavity, A, loads.inside.p0, &dc_dp);
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
    if (it == limit()) break;
    if (it >= 3 && r_rel > 1e3 * report.residual_norms[1] && r_rel > 1e-3) {
      report.failure = "Newton iteration diverges";
      return report;
    }
    if (problem_.free_dof_count() == 0) break;
    // Newton step; too long a step is recomputed on a stiffer foundation (see header).
    const double max_move =
        options_.max_move_per_edge * mean_edge_ + cavity_move(cavity, A.dV_du, c);
    const double stiffness_scale =
        A.K.diagonal().cwiseAbs().sum() / std::max(foundation_area_.sum(), 1e-300);
    double eta = eta_;
    eta_in_K_ = 0.0;
    Eigen::VectorXd du;
    double dp = 0.0, move = 0.0;
    // Modified-Newton reuse: with the wall already in equilibrium (r_ok) only the cavity
    // equation (first iteration of a step) or the increment test (last one) is unmet, the
    // correction is small and the last tangent, from this solve or the converged state of
    // the previous one, serves it as well as a new factorization would. Optionally also
    // while the residual falls fast (chord iterations, options_.reuse_tangent_ratio).
    // Every other iteration factorizes its own tangent (quadratic convergence).
    const bool converging_fast =
        it >= 1 &&
        report.residual_norms[it] <= options_.reuse_tangent_ratio * report.residual_norms[it - 1];
    const bool reuse = (r_ok || converging_fast) && reusable && eta == 0.0;
    for (int attempt = 0;; ++attempt) {
      if (!bordered_step(cavity, c, dc_dp, eta, reuse && attempt == 0, du, dp, report.failure))
        return report;
      reusable = true;
      move = du.size() ? du.cwiseAbs().maxCoeff() : 0.0;
      if (max_move <= 0.0 || move <= max_move || attempt == 12) break;
      eta = eta > 0.0 ? 10.0 * eta : 1e-6 * stiffness_scale;
    }
    if (eta > 0.0) ++report.regularized_iterations;
    eta_ = eta > 1e-9 * stiffness_scale ? 0.1 * eta : 0.0;
    if (options_.line_search && problem_.tension_field() && it > 0) {
      assembled = line_search(cavity, loads, du, dp, x);
      move *= line_search_step_;
    } else {
      problem_.apply_increment(du, x);
      loads.inside.p0 += dp;
    }
    last_increment = move;
  }
  report.failure = "no convergence in " + std::to_string(report.iterations) + " iterations";
  return report;
}

}  // namespace vesica::simulate
