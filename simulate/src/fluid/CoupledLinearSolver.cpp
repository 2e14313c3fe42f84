#include "fluid/CoupledLinearSolver.h"

#include <chrono>

#include <Eigen/UmfPackSupport>
#include <unsupported/Eigen/IterativeSolvers>

namespace vesica::simulate::fluid {
namespace {

// GMRES on the scaled system: converged when the preconditioned residual has fallen by
// this factor. Newton then converges linearly at about this rate per iteration, well
// inside its own increment tolerances after a few iterations.
constexpr double kKrylovTolerance = 1e-7;
// Iterations of one GMRES run (no restart inside it): beyond these an old LU is too far
// from the Jacobian, and a factorization is cheaper than more iterations.
constexpr int kKrylovBudget = 40;
// A run that needed more than this many iterations converged, but the next solve starts
// from a fresh factorization.
constexpr int kSlowKrylov = kKrylovBudget / 2;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

using UmfPack = Eigen::UmfPackLU<Eigen::SparseMatrix<double>>;

// The LU of an earlier Jacobian as GMRES's (left) preconditioner, in scaled unknowns:
// M⁻¹ t = D⁻¹ LU⁻¹ t for the operator J D.
class ReusedLu {
 public:
  ReusedLu() = default;
  template <typename MatrixType>
  explicit ReusedLu(const MatrixType& /*J*/) {}
  void set(const UmfPack* lu, const Eigen::VectorXd* scale) {
    lu_ = lu;
    scale_ = scale;
  }
  template <typename MatrixType>
  ReusedLu& analyzePattern(const MatrixType& /*J*/) {
    return *this;
  }
  template <typename MatrixType>
  ReusedLu& factorize(const MatrixType& /*J*/) {
    return *this;
  }
  template <typename MatrixType>
  ReusedLu& compute(const MatrixType& /*J*/) {
    return *this;
  }
  Eigen::VectorXd solve(const Eigen::VectorXd& t) const {
    Eigen::VectorXd x = lu_->solve(t);
    return x.cwiseQuotient(*scale_);
  }
  Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  const UmfPack* lu_ = nullptr;
  const Eigen::VectorXd* scale_ = nullptr;
};

}  // namespace

struct CoupledLinearSolver::Lu {
  Lu() {
    // Newton corrects a solve's round-off at its next iteration: no iterative refinement.
    umfpack.umfpackControl()(UMFPACK_IRSTEP) = 0;
    umfpack.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
  }
  UmfPack umfpack;
  bool analyzed = false, factorized = false;
};

CoupledLinearSolver::CoupledLinearSolver(Level2LinearSolver method) : method_(method) {
  reset();
}

CoupledLinearSolver::~CoupledLinearSolver() = default;

void CoupledLinearSolver::reset() {
  lu_ = std::make_unique<Lu>();
  factorized_ = {};
  refactorize_next_ = false;
}

bool CoupledLinearSolver::factorize(const Eigen::SparseMatrix<double>& J, std::string& failure) {
  const auto start = Clock::now();
  ++statistics_.factorizations;
  if (!lu_->analyzed) {
    // The pattern alone (values one), so that the analysis does not depend on which
    // Jacobian came first.
    Eigen::SparseMatrix<double> pattern = J;
    pattern.coeffs().setOnes();
    lu_->umfpack.analyzePattern(pattern);
    lu_->analyzed = true;
  }
  lu_->umfpack.factorize(J);
  const bool ok = lu_->factorized = lu_->umfpack.info() == Eigen::Success;
  statistics_.factorize_s += seconds_since(start);
  if (!ok) {
    factorized_ = {};
    failure = "could not factorize the coupled Jacobian";
    return false;
  }
  factorized_ = J;
  refactorize_next_ = false;
  return true;
}

bool CoupledLinearSolver::restore(const Eigen::SparseMatrix<double>& factorized) {
  reset();
  if (factorized.size() == 0) return true;  // nothing was factorized yet
  std::string failure;
  return factorize(factorized, failure);
}

bool CoupledLinearSolver::krylov(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r,
                                 const Eigen::VectorXd& scale, Eigen::VectorXd& dz) {
  Eigen::SparseMatrix<double> JD = J * scale.asDiagonal();
  Eigen::GMRES<Eigen::SparseMatrix<double>, ReusedLu> gmres;
  gmres.set_restart(kKrylovBudget);
  gmres.setMaxIterations(kKrylovBudget);
  gmres.setTolerance(kKrylovTolerance);
  gmres.preconditioner().set(&lu_->umfpack, &scale);
  gmres.compute(JD);
  const Eigen::VectorXd y = gmres.solve(-r);
  statistics_.krylov_iterations += static_cast<int>(gmres.iterations());
  if (gmres.info() != Eigen::Success || !y.allFinite()) {
    ++statistics_.krylov_fallbacks;
    return false;
  }
  ++statistics_.krylov_solves;
  refactorize_next_ = gmres.iterations() > kSlowKrylov;
  dz = scale.cwiseProduct(y);
  return true;
}

bool CoupledLinearSolver::solve(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r,
                                const Eigen::VectorXd& scale, Eigen::VectorXd& dz,
                                std::string& failure) {
  const auto start = Clock::now();
  const bool reuse = method_ == Level2LinearSolver::Krylov && lu_->factorized &&
                     !refactorize_next_ && factorized_.rows() == J.rows();
  bool solved = reuse && krylov(J, r, scale, dz);
  if (!solved) {
    if (!factorize(J, failure)) return false;
    dz = -lu_->umfpack.solve(r);
  }
  statistics_.solve_s += seconds_since(start);
  if (!dz.allFinite()) {
    failure = "non-finite Newton increment";
    return false;
  }
  return true;
}

nlohmann::json CoupledLinearSolver::json() const {
  const Statistics& s = statistics_;
  return {{"method", method_ == Level2LinearSolver::Krylov ? "krylov" : "direct"},
          {"factorizations", s.factorizations},
          {"krylov_solves", s.krylov_solves},
          {"krylov_iterations", s.krylov_iterations},
          {"krylov_fallbacks", s.krylov_fallbacks},
          {"factorize_s", s.factorize_s},
          {"linear_solve_s", s.solve_s}};
}

}  // namespace vesica::simulate::fluid
