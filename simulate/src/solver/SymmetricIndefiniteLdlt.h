#pragma once
// Sparse LDLᵀ of a symmetric, possibly indefinite matrix: MUMPS's multifrontal
// factorization with threshold (1×1 and 2×2) pivoting, sequential build. Under volume
// control past the pressure limit point the wall tangent K is symmetric but indefinite;
// Cholesky fails there, and an unsymmetric LU of it costs about three times as much, while
// this costs about as much as a Cholesky of a definite matrix of the same pattern. The
// factorization also gives K's inertia: the number of negative pivots is the number of
// negative eigenvalues (Sylvester).
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace vesica::simulate {

class SymmetricIndefiniteLdlt {
 public:
  SymmetricIndefiniteLdlt();
  ~SymmetricIndefiniteLdlt();
  SymmetricIndefiniteLdlt(const SymmetricIndefiniteLdlt&) = delete;
  SymmetricIndefiniteLdlt& operator=(const SymmetricIndefiniteLdlt&) = delete;

  // Factorizes K (compressed, symmetric; only its lower triangle is read). K keeps one
  // sparsity pattern (LinearSolver.h), so the ordering and symbolic analysis are done at
  // the first call only. Returns false when MUMPS reports an error (e.g. a singular K).
  bool factorize(const Eigen::SparseMatrix<double>& K);
  // X = K⁻¹ B for the last factorized K.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  // Negative pivots of the last factorization = negative eigenvalues of K.
  int negative_pivots() const { return negative_pivots_; }

 private:
  void analyze(const Eigen::SparseMatrix<double>& K);

  struct Mumps;  // the MUMPS instance (dmumps_c.h stays out of this header)
  std::unique_ptr<Mumps> mumps_;
  std::vector<int> lower_slot_;  // entry k of the lower triangle → index in K's values
  std::vector<double> values_;   // the lower triangle handed to MUMPS
  bool analyzed_ = false;
  int negative_pivots_ = 0;
};

}  // namespace vesica::simulate
