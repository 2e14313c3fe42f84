#include "solver/SymmetricIndefiniteLdlt.h"

#include <algorithm>
#include <limits>

#include <dmumps_c.h>

namespace vesica::simulate {
namespace {

// MUMPS's job codes and the special communicator value of its C interface.
constexpr int kInit = -1, kEnd = -2, kAnalyze = 1, kFactorize = 2, kSolve = 3;
constexpr int kUseCommWorld = -987654;
// Error codes of a too small workspace: the pivots delayed by the indefinite matrix need
// more room than the analysis estimated. Doubling the relaxation (ICNTL(14), percent)
// and factorizing again is MUMPS's documented remedy.
constexpr int kWorkspaceTooSmall[] = {-8, -9, -11, -12, -14, -15};
constexpr int kMaxWorkspaceRetries = 4;

// ICNTL(i) and INFOG(i) in the manual's 1-based numbering.
int& icntl(DMUMPS_STRUC_C& id, int i) {
  return id.icntl[i - 1];
}
int infog(const DMUMPS_STRUC_C& id, int i) {
  return id.infog[i - 1];
}

}  // namespace

struct SymmetricIndefiniteLdlt::Mumps {
  DMUMPS_STRUC_C id{};
  std::vector<MUMPS_INT> rows, cols;  // 1-based coordinates of the lower triangle

  Mumps() {
    id.comm_fortran = kUseCommWorld;
    id.par = 1;  // the host works too (there is only the host)
    id.sym = 2;  // general symmetric: indefinite allowed
    id.job = kInit;
    dmumps_c(&id);
    // Silence: no error, diagnostic or statistics output (failures are returned).
    icntl(id, 1) = icntl(id, 2) = icntl(id, 3) = -1;
    icntl(id, 4) = 0;
    icntl(id, 7) = 7;   // ordering: MUMPS's automatic choice
    icntl(id, 24) = 1;  // detect null pivots, so that a singular K is reported as such
  }
  ~Mumps() {
    id.job = kEnd;
    dmumps_c(&id);
  }
  void run(int job) {
    id.job = job;
    dmumps_c(&id);
  }
};

SymmetricIndefiniteLdlt::SymmetricIndefiniteLdlt() : mumps_(std::make_unique<Mumps>()) {}
SymmetricIndefiniteLdlt::~SymmetricIndefiniteLdlt() = default;

void SymmetricIndefiniteLdlt::analyze(const Eigen::SparseMatrix<double>& K) {
  Mumps& m = *mumps_;
  m.rows.clear();
  m.cols.clear();
  lower_slot_.clear();
  const int* outer = K.outerIndexPtr();
  const int* inner = K.innerIndexPtr();
  for (int j = 0; j < K.outerSize(); ++j)
    for (int k = outer[j]; k < outer[j + 1]; ++k)
      if (inner[k] >= j) {
        m.rows.push_back(inner[k] + 1);
        m.cols.push_back(j + 1);
        lower_slot_.push_back(k);
      }
  values_.resize(lower_slot_.size());
  m.id.n = static_cast<MUMPS_INT>(K.rows());
  m.id.nnz = static_cast<MUMPS_INT8>(lower_slot_.size());
  m.id.irn = m.rows.data();
  m.id.jcn = m.cols.data();
  m.id.a = values_.data();
  m.run(kAnalyze);
  analyzed_ = infog(m.id, 1) >= 0;
}

bool SymmetricIndefiniteLdlt::factorize(const Eigen::SparseMatrix<double>& K) {
  if (!analyzed_) analyze(K);
  if (!analyzed_) return false;
  const double* v = K.valuePtr();
  for (std::size_t k = 0; k < lower_slot_.size(); ++k) values_[k] = v[lower_slot_[k]];
  Mumps& m = *mumps_;
  for (int retry = 0;; ++retry) {
    m.run(kFactorize);
    const int status = infog(m.id, 1);
    bool workspace = false;
    for (int code : kWorkspaceTooSmall) workspace = workspace || status == code;
    if (!workspace || retry == kMaxWorkspaceRetries) break;
    icntl(m.id, 14) = 2 * std::max(icntl(m.id, 14), 20);
  }
  negative_pivots_ = infog(m.id, 12);
  return infog(m.id, 1) >= 0 && infog(m.id, 28) == 0;  // INFOG(28): null pivots found
}

Eigen::MatrixXd SymmetricIndefiniteLdlt::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X = B;  // MUMPS overwrites the right-hand sides with the solutions
  Mumps& m = *mumps_;
  m.id.rhs = X.data();
  m.id.nrhs = static_cast<MUMPS_INT>(X.cols());
  m.id.lrhs = static_cast<MUMPS_INT>(X.rows());
  m.run(kSolve);
  m.id.rhs = nullptr;
  // A failed solve returns NaN, which Newton reports as a non-finite increment.
  if (infog(m.id, 1) < 0) X.setConstant(std::numeric_limits<double>::quiet_NaN());
  return X;
}

}  // namespace vesica::simulate
