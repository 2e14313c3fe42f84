#pragma once
// The sparse direct solver of every Newton tangent K in simulate. K keeps one sparsity
// pattern for the solver's life, so the fill-reducing ordering and symbolic analysis are
// done once. For the wall's tangent (Symmetry::Detect) each factorization takes the
// fastest exact route:
//  - K symmetric (pressure without hydrostatic gradient) and positive definite: CHOLMOD
//    supernodal Cholesky;
//  - K symmetric but indefinite (volume control past the pressure limit point, a follower
//    pressure on a slack wall): MUMPS LDLᵀ with threshold pivoting, a third of the cost
//    of an LU and close to a Cholesky's (SymmetricIndefiniteLdlt.h). Its inertia says when
//    K is definite again, and the next factorization returns to Cholesky;
//  - otherwise (follower pressure with a gradient): UMFPACK LU with partial pivoting.
// A system known to be unsymmetric (the Navier–Stokes and coupled wall–urine Jacobians,
// Symmetry::Unsymmetric) goes to UMFPACK LU directly, without the symmetry check.
// All are exact factorizations of K, so Newton's quadratic convergence is untouched. The
// LU refines its solutions iteratively only when asked (Refinement::Iterative, UMFPACK's
// default of up to two steps): Newton corrects a solve error at its next iteration anyway,
// except where its convergence test asks increments below the solve's round-off (the
// urine alone at rest, FluidNewton).
// Dense kernels run in the system BLAS (OpenBLAS when installed; see docs/simulate.md).
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace vesica::simulate {

class LinearSolver {
 public:
  enum class Symmetry { Detect, Unsymmetric };
  enum class Refinement { None, Iterative };
  explicit LinearSolver(Symmetry symmetry = Symmetry::Detect,
                        Refinement refinement = Refinement::None);
  ~LinearSolver();
  LinearSolver(const LinearSolver&) = delete;
  LinearSolver& operator=(const LinearSolver&) = delete;

  // Factorizes K (compressed, structurally symmetric pattern, the same on every call).
  // Returns false when K is singular.
  bool factorize(const Eigen::SparseMatrix<double>& K);
  bool factorized() const { return factorized_; }
  // X = K⁻¹ B for the last factorized K; B has one column per right-hand side.
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  // Which factorization the last call used (for tests and logs).
  enum class Method { None, Cholesky, SymmetricIndefinite, LU };
  Method method() const { return method_; }
  bool used_cholesky() const { return method_ == Method::Cholesky; }
  // K's number of negative eigenvalues when the last factorization tells it (Cholesky: 0,
  // LDLᵀ: its negative pivots), else -1 (LU). Under volume control it counts the modes
  // past their limit point.
  int negative_eigenvalues() const;

  // What a solver carries to the next factorization and solve (checkpoints): the last
  // factorized K (kept only when asked: keep_last_matrix) and the Cholesky-first rule
  // before and after that factorization. restore() factorizes that K again, so that a
  // solver restored from it solves bit for bit as the one saved would.
  struct Memory {
    Eigen::SparseMatrix<double> matrix;  // empty: none factorized, or not kept
    bool try_cholesky_before = true, try_cholesky = true;
  };
  void keep_last_matrix(bool on) { keep_last_matrix_ = on; }
  Memory memory() const { return {last_matrix_, try_cholesky_before_, try_cholesky_}; }
  void restore(const Memory& memory);

 private:
  bool is_symmetric(const Eigen::SparseMatrix<double>& K);
  bool factorize_lu(const Eigen::SparseMatrix<double>& K);

  struct Backends;
  std::unique_ptr<Backends> backends_;
  Symmetry symmetry_;
  std::vector<int> transpose_slot_;  // entry k = (i, j) → index of (j, i)
  bool factorized_ = false;
  Method method_ = Method::None;
  // Whether the next symmetric K is tried by Cholesky first: until K is found indefinite,
  // and again once the LDLᵀ finds no negative pivot (a failed Cholesky costs up to a
  // whole factorization, so it is not retried while K is known to be indefinite).
  bool try_cholesky_ = true;
  bool try_cholesky_before_ = true;  // of the last factorization
  bool keep_last_matrix_ = false;
  Eigen::SparseMatrix<double> last_matrix_;
};

}  // namespace vesica::simulate
