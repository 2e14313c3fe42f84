#include "solver/LinearSolver.h"

#include "solver/SymmetricIndefiniteLdlt.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <mutex>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <dlfcn.h>
#include <omp.h>

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

namespace vesica::simulate {
namespace {

// K counts as symmetric when no pair of mirror entries differs by more than this fraction
// of its largest entry: a tangent error of 1e-14 is far below what Newton's quadratic
// convergence can see (the residual floor is ~1e-12), while a hydrostatic gradient makes
// K asymmetric by ρ g h / p ≫ 1e-14.
constexpr double kSymmetryTolerance = 1e-14;

// UMFPACK allocates and frees its multi-megabyte numeric workspace at every factorization.
// glibc serves such blocks by mmap and returns them to the system at free, so each
// factorization page-faults its whole workspace in again, a large share of a
// calibration's CPU time. Keeping blocks up to 32 MiB (glibc's largest
// allowed threshold) in the heap and not trimming it lets the next factorization reuse
// the same pages. Process-wide, once; the cost is that freed memory stays with the process.
void keep_solver_workspaces_resident() {
#if defined(__GLIBC__)
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
    mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
  });
#endif
}

// Debian's CHOLMOD opens an OpenMP team (up to 4 threads, more than our 2 cores) for each
// supernode to copy K into the factor: memory-bound work that the team's wake-ups and
// waits make slower than serial copying. The dense work runs in the BLAS's own threads
// and the element loop in ours, so OpenMP regions run serially. Process-wide, once.
void serialize_openmp_regions() {
  static std::once_flag once;
  std::call_once(once, [] { omp_set_max_active_levels(0); });
}

// The supernodes of a membrane tangent are small (a few hundred columns), too small for
// BLAS threads to pay off, and the element loop already uses the cores: with OpenBLAS as
// the system BLAS, one BLAS thread unless OPENBLAS_NUM_THREADS says otherwise (two BLAS
// threads cost more CPU time and were slower on a shared 2-core machine). The BLAS
// is whatever libblas.so.3 points to, so OpenBLAS is looked up at run time.
void single_threaded_blas() {
  static std::once_flag once;
  std::call_once(once, [] {
    if (std::getenv("OPENBLAS_NUM_THREADS")) return;
    using SetThreads = void (*)(int);
    if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
      set(1);
  });
}

}  // namespace

struct LinearSolver::Backends {
  using Matrix = Eigen::SparseMatrix<double>;
  Eigen::UmfPackLU<Matrix> lu;
  Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> llt;
  // MUMPS is started only when a symmetric indefinite K first needs it.
  std::unique_ptr<SymmetricIndefiniteLdlt> ldlt;
  bool lu_analyzed = false, llt_analyzed = false;
};

LinearSolver::LinearSolver(Symmetry symmetry, Refinement refinement)
    : backends_(std::make_unique<Backends>()), symmetry_(symmetry) {
  keep_solver_workspaces_resident();
  serialize_openmp_regions();
  single_threaded_blas();
  // Newton corrects any solve error at the next iteration, so UMFPACK's iterative
  // refinement (two extra residual evaluations and solves per right-hand side) only costs
  // unless asked for.
  if (refinement == Refinement::None) backends_->lu.umfpackControl()(UMFPACK_IRSTEP) = 0;
  // A not-positive-definite K is an expected outcome (we then fall back to LDLᵀ): no
  // CHOLMOD warning on stdout.
  backends_->llt.cholmod().print = 0;
  // Fill-reducing ordering: AMD and METIS both tried once, the one with less fill kept.
  // CHOLMOD's default stops at AMD when its fill looks acceptable, but on a membrane mesh
  // nested dissection is better (less fill and fewer flops per factorization on a large
  // sphere), for a little more analysis once per run.
  cholmod_common& c = backends_->llt.cholmod();
  c.nmethods = 2;
  c.method[0].ordering = CHOLMOD_AMD;
  c.method[1].ordering = CHOLMOD_METIS;
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

bool LinearSolver::factorize_lu(const Eigen::SparseMatrix<double>& K) {
  Backends& b = *backends_;
  if (!b.lu_analyzed) {
    b.lu.analyzePattern(K);
    b.lu_analyzed = true;
  }
  b.lu.factorize(K);
  factorized_ = b.lu.info() == Eigen::Success;
  method_ = Method::LU;
  return factorized_;
}

void LinearSolver::restore(const Memory& memory) {
  if (memory.matrix.nonZeros() > 0) {
    try_cholesky_ = memory.try_cholesky_before;
    factorize(memory.matrix);
  }
  try_cholesky_before_ = memory.try_cholesky_before;
  try_cholesky_ = memory.try_cholesky;
}

bool LinearSolver::factorize(const Eigen::SparseMatrix<double>& K) {
  try_cholesky_before_ = try_cholesky_;
  if (keep_last_matrix_) last_matrix_ = K;
  factorized_ = false;
  method_ = Method::None;
  Backends& b = *backends_;
  if (symmetry_ == Symmetry::Unsymmetric || !is_symmetric(K)) return factorize_lu(K);
  if (try_cholesky_) {
    if (!b.llt_analyzed) {
      b.llt.analyzePattern(K);
      b.llt_analyzed = true;
    }
    b.llt.factorize(K);
    if (b.llt.info() == Eigen::Success) {
      factorized_ = true;
      method_ = Method::Cholesky;
      return true;
    }
  }
  if (!b.ldlt) b.ldlt = std::make_unique<SymmetricIndefiniteLdlt>();
  factorized_ = b.ldlt->factorize(K);
  method_ = Method::SymmetricIndefinite;
  try_cholesky_ = factorized_ && b.ldlt->negative_pivots() == 0;
  return factorized_;
}

int LinearSolver::negative_eigenvalues() const {
  switch (method_) {
    case Method::Cholesky:
      return 0;
    case Method::SymmetricIndefinite:
      return backends_->ldlt->negative_pivots();
    default:
      return -1;
  }
}

Eigen::MatrixXd LinearSolver::solve(const Eigen::MatrixXd& B) const {
  switch (method_) {
    case Method::Cholesky:
      return backends_->llt.solve(B);
    case Method::SymmetricIndefinite:
      return backends_->ldlt->solve(B);
    default:
      return backends_->lu.solve(B);
  }
}

}  // namespace vesica::simulate
