#include "solver/NewtonSolver.h"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "solver/LinearSolver.h"
#include "solver/PreconditionedGmres.h"
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
// farthest dof by |c| |g|∞ / |g|². That much motion is demanded by the load, not a sign
// of a slack mode, so the move limit of a Newton step adds it: without it a filling step
// of a refined wall (edges shorter than the wall's uniform outward move of the step) was
// taken for a runaway step and crawled on the foundation.
double cavity_move(const CavityEquation& cavity, const Eigen::VectorXd& g, double c) {
  if (!cavity.volume_control || g.size() == 0) return 0.0;
  const double g2 = g.squaredNorm();
  return g2 > 0.0 ? std::abs(c) * g.cwiseAbs().maxCoeff() / g2 : 0.0;
}

}  // namespace

// One solve's view of the wall and its cavity as a NewtonSystem: the iterate is (x, p0).
class NewtonSolver::System final : public NewtonSystem {
 public:
  System(NewtonSolver& solver, const NewtonOptions& options, const CavityEquation& cavity,
         WallLoads& loads, std::vector<Eigen::Vector3d>& x)
      : problem_(solver.problem_),
        options_(options),
        assembly_(solver.assembly_),
        lu_(*solver.lu_),
        size_(solver.size_),
        cavity_(cavity),
        loads_(loads),
        x_(x) {}

  std::size_t unknown_count() const override { return problem_.free_dof_count(); }

  bool increment_converged(int increments, double move) const override {
    return increments == 0 || move <= options_.increment_tolerance * size_;
  }
  bool tests_residual() const override { return true; }

  void evaluate() override { problem_.assemble(x_, loads_, true, assembly_); }

  ResidualCheck check_residual() override {
    const WallAssembly& A = assembly_;
    c_ = cavity_residual(cavity_, A, loads_.inside.p0, &dc_dp_);
    ResidualCheck check;
    check.norm = A.residual.norm() / std::max(A.force_scale, 1e-300);
    // Near zero load the relative test is meaningless: a residual that would move the
    // model by 1e-13 of its size through the stiffest dof counts as zero.
    const double floor =
        1e-13 * size_ * (A.K.nonZeros() ? A.K.diagonal().cwiseAbs().maxCoeff() : 0.0);
    check.equilibrium = A.residual.norm() <= options_.residual_tolerance * A.force_scale ||
                        A.residual.norm() <= floor;
    const double c_scale = cavity_.volume_control ? std::abs(A.volume) : 1.0;
    const bool c_ok = std::abs(c_) <= options_.volume_tolerance * c_scale ||
                      (!cavity_.volume_control && c_ == 0.0);
    check.converged = check.equilibrium && c_ok;
    vesica::log()->debug("newton: |r|/|f| = {:.3e}, |r| = {:.3e} N, c = {:.3e}, p0 = {:.6g} Pa",
                         check.norm, A.residual.norm(), c_, loads_.inside.p0);
    if (!std::isfinite(check.norm) || !std::isfinite(c_)) check.failure = "residual is not finite";
    return check;
  }

  Eigen::SparseMatrix<double>& tangent() override { return assembly_.K; }
  double demanded_move() const override { return cavity_move(cavity_, assembly_.dV_du, c_); }

  // The bordered step by the Schur complement of K.
  bool solve_increment(bool reuse, std::string& failure) override {
    const WallAssembly& A = assembly_;
    const bool preconditioned = options_.preconditioned_reuse.max_iterations > 0;
    // u_p is needed whenever p0 changes: always under volume control, under pressure
    // control only until p0 equals the prescribed pressure. There Δp0 = −c is known, and
    // where each right-hand side costs GMRES solves (preconditioned reuse) the increment
    // is one: Δu = −K⁻¹ (r + Δp0 ∂r/∂p0).
    const bool combined = preconditioned && !cavity_.volume_control;
    const bool need_u_p = (cavity_.volume_control || c_ != 0.0) && !combined;
    Eigen::MatrixXd B(A.residual.size(), need_u_p ? 2 : 1);
    B.col(0) =
        combined ? Eigen::VectorXd(c_ * A.dr_dp0 - A.residual) : Eigen::VectorXd(-A.residual);
    if (need_u_p) B.col(1) = -A.dr_dp0;
    Eigen::MatrixXd U;
    stale_ = false;
    if (!reuse || (preconditioned && !preconditioned_solve(B, U))) {
      if (!lu_.factorize(A.K)) {
        failure = "singular tangent matrix";
        return false;
      }
      U = lu_.solve(B);
      stale_ = false;
    } else if (!preconditioned) {
      U = lu_.solve(B);
    }
    if (need_u_p) u_p_ = U.col(1);
    dp_ = 0.0;
    if (cavity_.volume_control) {
      const double denom = A.dV_du.dot(U.col(1)) + dc_dp_;
      if (denom == 0.0) {
        failure = "singular cavity equation";
        return false;
      }
      dp_ = (-c_ - A.dV_du.dot(U.col(0))) / denom;
    } else {
      dp_ = -c_;
    }
    du_ = need_u_p ? Eigen::VectorXd(U.col(0) + dp_ * U.col(1)) : Eigen::VectorXd(U.col(0));
    if (!du_.allFinite()) {
      failure = "increment is not finite";
      return false;
    }
    return true;
  }

  bool factorization_reusable() const override { return !stale_; }

  double increment_move() const override { return du_.size() ? du_.cwiseAbs().maxCoeff() : 0.0; }

  void apply_increment() override {
    problem_.apply_increment(du_, x_);
    loads_.inside.p0 += dp_;
  }

  bool line_search_applies() const override { return problem_.tension_field(); }

  double begin_line_search() override {
    r_ref_ = std::max(assembly_.residual.norm(), 1e-6 * assembly_.force_scale);
    c_ref_ = std::max(std::abs(cavity_residual(cavity_, assembly_, loads_.inside.p0)),
                      1e-8 * std::abs(assembly_.volume));
    x_start_ = x_;
    p_start_ = loads_.inside.p0;
    return merit(assembly_, loads_.inside.p0);
  }

  bool try_fraction(double fraction, double& merit_out) override {
    x_ = x_start_;
    problem_.apply_increment(fraction * du_, x_);
    loads_.inside.p0 = p_start_ + fraction * dp_;
    try {
      problem_.assemble(x_, loads_, true, trial_);
    } catch (const std::runtime_error&) {
      return false;  // an inverted element: the step is too long
    }
    merit_out = merit(trial_, loads_.inside.p0);
    return true;
  }

  void keep_trial() override { std::swap(assembly_, trial_); }

 private:
  // U = K⁻¹ B by GMRES preconditioned by the last factorization (NewtonOptions.h); false
  // where a column does not meet the tolerance. stale_: the factorization is far enough
  // from K that the next increment factorizes afresh.
  bool preconditioned_solve(const Eigen::MatrixXd& B, Eigen::MatrixXd& U) {
    const PreconditionedReuseOptions& o = options_.preconditioned_reuse;
    const auto precondition = [this](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      return lu_.solve(v);
    };
    U.resize(B.rows(), B.cols());
    for (Eigen::Index j = 0; j < B.cols(); ++j) {
      // u_p's right-hand side, ∂r/∂p0, changes little from one iteration to the next.
      Eigen::VectorXd x = j == 1 ? u_p_ : Eigen::VectorXd();
      const GmresResult r = preconditioned_gmres(assembly_.K, precondition, B.col(j), o.tolerance,
                                                 o.max_iterations, x);
      if (!r.converged) return false;
      stale_ = stale_ || r.iterations > o.refactorize_after;
      U.col(j) = x;
    }
    return true;
  }

  double merit(const WallAssembly& a, double p0) const {
    const double r = a.residual.norm() / r_ref_, c = cavity_residual(cavity_, a, p0) / c_ref_;
    return r * r + c * c;
  }

  MembraneProblem& problem_;
  const NewtonOptions& options_;
  WallAssembly& assembly_;
  LinearSolver& lu_;
  const double size_;
  const CavityEquation& cavity_;
  WallLoads& loads_;
  std::vector<Eigen::Vector3d>& x_;
  double c_ = 0.0, dc_dp_ = 0.0;  // cavity residual at the iterate and dc/dp0
  bool stale_ = false;            // the last increment's factorization (preconditioned_solve)
  Eigen::VectorXd u_p_;           // −K⁻¹ ∂r/∂p0 of the last increment
  Eigen::VectorXd du_;            // the increment (free dofs, m) and of p0 (Pa)
  double dp_ = 0.0;
  // Line search: the start iterate, the references of the merit and the trial assembly.
  std::vector<Eigen::Vector3d> x_start_;
  double p_start_ = 0.0, r_ref_ = 1.0, c_ref_ = 1.0;
  WallAssembly trial_;
};

NewtonSolver::NewtonSolver(MembraneProblem& problem, NewtonOptions options)
    : problem_(problem),
      loop_(options, ElasticFoundation(problem, options.foundation)),
      lu_(std::make_unique<LinearSolver>()) {
  Eigen::AlignedBox3d box;
  for (const auto& p : problem.wall().nodes) box.extend(p);
  size_ = box.diagonal().norm();
}

NewtonSolver::~NewtonSolver() = default;

void NewtonSolver::keep_factorized_matrix() {
  lu_->keep_last_matrix(true);
}

NewtonSolver::Carried NewtonSolver::carried() const {
  return {loop_.carried(), lu_->memory()};
}

void NewtonSolver::restore(const Carried& carried) {
  loop_.restore(carried.loop);
  // The factorization matters only where the next solve may reuse it.
  LinearSolver::Memory lu = carried.lu;
  if (!carried.loop.tangent_reusable) lu.matrix = {};
  lu_->restore(lu);
}

NewtonReport NewtonSolver::solve(const CavityEquation& cavity, WallLoads& loads,
                                 std::vector<Eigen::Vector3d>& x) {
  System system(*this, loop_.options(), cavity, loads, x);
  return loop_.solve(system);
}

}  // namespace vesica::simulate
