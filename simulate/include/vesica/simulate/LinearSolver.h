#pragma once
// The sparse direct solver of the Newton tangent K (free dofs; N/m). K keeps one sparsity
// pattern for the whole run, so the fill-reducing ordering and symbolic analysis are done
// once. Each factorization takes the fastest exact route:
//  - K symmetric (pressure without hydrostatic gradient) and positive definite: CHOLMOD
//    supernodal Cholesky, about half the work of an LU;
//  - otherwise (follower pressure with a gradient, or indefinite past the limit point):
//    UMFPACK LU with partial pivoting.
// Both are exact factorizations of K, so Newton's quadratic convergence is untouched.
// Dense kernels run in the system BLAS (OpenBLAS when installed; see docs/simulate.md).
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace vesica::simulate {

class LinearSolver {
 public:
  LinearSolver();
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  // Factorizes K (compressed, structurally symmetric pattern, the same on every call).
  // Returns false when K is singular.
  bool factorize(const Eigen::SparseMatrix<double>& K);
  bool factorized() const { return factorized_; }
  // X = K⁻¹ B for the last factorized K; B has one column per right-hand side.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  // Whether the last factorization was the Cholesky one (for tests and logs).
  bool used_cholesky() const { return used_cholesky_; }

 private:
  bool is_symmetric(const Eigen::SparseMatrix<double>& K);

  struct Backends;
  std::unique_ptr<Backends> backends_;
  std::vector<int> transpose_slot_;  // entry k = (i, j) → index of (j, i)
  bool factorized_ = false, used_cholesky_ = false;
  int cholesky_skips_ = 0;  // LU-only factorizations left after K was found indefinite
  int last_skips_ = 0;      // the last such count (grows while K stays indefinite)
};

}  // namespace vesica::simulate
