#include "vesica/simulate/LinearSolver.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

namespace vesica::simulate {
namespace {

// K counts as symmetric when no pair of mirror entries differs by more than this fraction
// of its largest entry: a tangent error of 1e-14 is far below what Newton's quadratic
// convergence can see (the residual floor is ~1e-12), while a hydrostatic gradient makes
// K asymmetric by ρ g h / p ≫ 1e-14.
constexpr double kSymmetryTolerance = 1e-14;
// After K was found indefinite (volume control past the limit point), this many LU
// factorizations are done before Cholesky is tried again, so a failed Cholesky attempt
// does not add to every iteration.
constexpr int kSkipsAfterIndefinite = 8;

}  // namespace

struct LinearSolver::Backends {
  using Matrix = Eigen::SparseMatrix<double>;
  Eigen::UmfPackLU<Matrix> lu;
  Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> llt;
  bool lu_analyzed = false, llt_analyzed = false;
};

LinearSolver::LinearSolver() : backends_(std::make_unique<Backends>()) {
  // Newton corrects any solve error at the next iteration, so UMFPACK's iterative
  // refinement (two extra residual evaluations and solves per right-hand side) only costs.
  backends_->lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
  // A not-positive-definite K is an expected outcome (we then fall back to LU): no
  // CHOLMOD warning on stdout.
  backends_->llt.cholmod().print = 0;
}

LinearSolver::~LinearSolver() = default;

bool LinearSolver::is_symmetric(const Eigen::SparseMatrix<double>& K) {
  const int nnz = static_cast<int>(K.nonZeros());
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  if (static_cast<int>(transpose_slot_.size()) != nnz) {
    transpose_slot_.assign(nnz, -1);
    for (int j = 0; j < K.outerSize(); ++j)
      for (int k = outer[j]; k < outer[j + 1]; ++k) {
        const int i = inner[k];
        const int* hit = std::lower_bound(inner + outer[i], inner + outer[i + 1], j);
        if (hit == inner + outer[i + 1] || *hit != j) return false;  // pattern not symmetric
        transpose_slot_[k] = static_cast<int>(hit - inner);
      }
  }
  const double* v = K.valuePtr();
  double largest = 0.0;
  for (int k = 0; k < nnz; ++k) largest = std::max(largest, std::abs(v[k]));
  const double tolerance = kSymmetryTolerance * largest;
  for (int k = 0; k < nnz; ++k)
    if (transpose_slot_[k] < 0 || std::abs(v[k] - v[transpose_slot_[k]]) > tolerance) return false;
  return true;
}

bool LinearSolver::factorize(const Eigen::SparseMatrix<double>& K) {
  factorized_ = used_cholesky_ = false;
  Backends& b = *backends_;
  if (cholesky_skips_ > 0) {
    --cholesky_skips_;
  } else if (is_symmetric(K)) {
    if (!b.llt_analyzed) {
      b.llt.analyzePattern(K);
      b.llt_analyzed = true;
    }
    b.llt.factorize(K);
    if (b.llt.info() == Eigen::Success) {
      factorized_ = used_cholesky_ = true;
      return true;
    }
    cholesky_skips_ = kSkipsAfterIndefinite;
  }
  if (!b.lu_analyzed) {
    b.lu.analyzePattern(K);
    b.lu_analyzed = true;
  }
  b.lu.factorize(K);
  factorized_ = b.lu.info() == Eigen::Success;
  return factorized_;
}

Eigen::MatrixXd LinearSolver::solve(const Eigen::MatrixXd& B) const {
  if (used_cholesky_) return backends_->llt.solve(B);
  return backends_->lu.solve(B);
}

}  // namespace vesica::simulate
