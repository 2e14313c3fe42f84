#pragma once
// The linear solve of each Newton iteration of the coupled wall–urine system
// (docs/navier-stokes.md §7). Two methods, chosen by Level2Options::linear_solver:
//  - Direct: a fresh sparse LU (UMFPACK, LinearSolver) of every Jacobian;
//  - Krylov (Newton–Krylov): GMRES on the current Jacobian, preconditioned by the LU
//    factors of an earlier one, reused across iterations and time steps while GMRES
//    converges in few iterations. The Jacobian drifts slowly from step to step (the
//    geometry by a small fraction, the same Δt), so an old LU is a near-exact inverse
//    and a GMRES iteration costs one sparse product and one pair of triangular solves
//    instead of a factorization. When GMRES does not reach its tolerance in its budget,
//    or needed more than half of it, the current Jacobian is factorized.
// The unknowns are scaled for GMRES (wall positions by the wall's size, urine velocities by
// size/Δt, pressures by the pressure scale) so that its residual norm weighs each kind
// alike: unscaled, the pressures (Pa) would drown the positions (m).
// The LU is UMFPACK's, called directly rather than through LinearSolver for two controls:
// a nested-dissection ordering (METIS), which on the 3-D urine mesh makes far less fill
// than the default AMD, and a symbolic analysis of the pattern alone (all values one), so
// that the factors depend only on the matrix factorized. The factorized matrix is kept,
// so that a restarted run factorizes the very same matrix again and continues bit for bit
// (docs/navier-stokes.md §7).
#include <memory>
#include <string>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <nlohmann/json.hpp>

#include "vesica/simulate/protocol/CystometrySettings.h"

namespace vesica::simulate::fluid {

class CoupledLinearSolver {
 public:
  explicit CoupledLinearSolver(Level2LinearSolver method = Level2LinearSolver::Krylov);

  // dz = −J⁻¹ r. scale: one positive value per unknown (the GMRES scaling). Returns false
  // with the reason when J is singular or the increment is not finite.
  bool solve(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r,
             const Eigen::VectorXd& scale, Eigen::VectorXd& dz, std::string& failure);

  CoupledLinearSolver(const CoupledLinearSolver&) = delete;
  CoupledLinearSolver& operator=(const CoupledLinearSolver&) = delete;
  ~CoupledLinearSolver();

  // Forgets the factors (new unknowns: the pattern changed).
  void reset();
  // The matrix whose factors are kept (empty when none); a restarted run factorizes it
  // again for the very same factors.
  const Eigen::SparseMatrix<double>& factorized_matrix() const { return factorized_; }
  bool restore(const Eigen::SparseMatrix<double>& factorized);

  struct Statistics {
    int factorizations = 0;
    int krylov_solves = 0;      // solves that GMRES finished
    int krylov_iterations = 0;  // over all GMRES runs, those that fell back included
    int krylov_fallbacks = 0;   // GMRES runs that did not converge (a factorization followed)
    double factorize_s = 0.0, solve_s = 0.0;  // wall-clock seconds
  };
  const Statistics& statistics() const { return statistics_; }
  nlohmann::json json() const;
  // The rest of what a restarted run needs (checkpoints): whether the next solve
  // factorizes anew, and the counts so far (set after restore()).
  bool refactorize_next() const { return refactorize_next_; }
  void restore_progress(bool refactorize_next, const Statistics& statistics) {
    refactorize_next_ = refactorize_next;
    statistics_ = statistics;
  }

 private:
  bool factorize(const Eigen::SparseMatrix<double>& J, std::string& failure);
  // GMRES with the kept factors; false when it did not converge.
  bool krylov(const Eigen::SparseMatrix<double>& J, const Eigen::VectorXd& r,
              const Eigen::VectorXd& scale, Eigen::VectorXd& dz);

  Level2LinearSolver method_;
  struct Lu;
  std::unique_ptr<Lu> lu_;
  Eigen::SparseMatrix<double> factorized_;
  bool refactorize_next_ = false;  // the last GMRES run was slow
  Statistics statistics_;
};

}  // namespace vesica::simulate::fluid
