// LinearSolver: each factorization route (Cholesky for symmetric positive definite K, LDLᵀ
// for symmetric indefinite K, LU otherwise) must reproduce a known solution x from
// b = K x, for the kinds of tangent
// Newton meets: stable (SPD), past a limit point (symmetric indefinite) and with a
// hydrostatic pressure gradient (non-symmetric). Dimensionless test matrices.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ChainMatrix.h"
#include "solver/LinearSolver.h"

using vesica::simulate::LinearSolver;
using vesica::test::chain;

namespace {

// A known solution with two columns (two right-hand sides, as Newton's bordered solve).
// K with row and column i set to zero (entries kept): singular, same pattern.
Eigen::SparseMatrix<double> with_zero_row_and_column(Eigen::SparseMatrix<double> K, int i) {
  for (int j = 0; j < K.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(K, j); it; ++it)
      if (it.row() == i || it.col() == i) it.valueRef() = 0.0;
  return K;
}

Eigen::MatrixXd known_solution(int n) {
  Eigen::MatrixXd X(n, 2);
  for (int i = 0; i < n; ++i) X(i, 0) = std::sin(0.1 * i) + 1.0, X(i, 1) = 0.01 * i * i - 3.0;
  return X;
}

double relative_error(const Eigen::MatrixXd& X, const Eigen::MatrixXd& exact) {
  return (X - exact).norm() / exact.norm();
}

}  // namespace

TEST(LinearSolver, SymmetricPositiveDefiniteUsesCholesky) {
  const auto K = chain(300, 0.0, 0.0);
  const Eigen::MatrixXd X = known_solution(300);
  LinearSolver solver;
  ASSERT_TRUE(solver.factorize(K));
  EXPECT_TRUE(solver.used_cholesky());
  EXPECT_LT(relative_error(solver.solve(K * X), X), 1e-10);
}

TEST(LinearSolver, SymmetricIndefiniteUsesLdltAndCountsNegativeEigenvalues) {
  // Eigenvalues 2 - 2 cos(kπ/301) - 0.5, k = 1..300: negative for cos(kπ/301) > 3/4,
  // i.e. k ≤ 301 acos(3/4)/π = 69.2, so 69 of them; none is zero.
  const auto K = chain(300, 0.5, 0.0);
  const Eigen::MatrixXd X = known_solution(300);
  LinearSolver solver;
  ASSERT_TRUE(solver.factorize(K));
  EXPECT_EQ(solver.method(), LinearSolver::Method::SymmetricIndefinite);
  EXPECT_EQ(solver.negative_eigenvalues(), 69);
  EXPECT_LT(relative_error(solver.solve(K * X), X), 1e-10);
  // While K is known to be indefinite, the next one goes straight to LDLᵀ: an SPD matrix
  // with the same pattern is solved exactly, its inertia (no negative eigenvalue) is seen,
  // and from then on Cholesky is used again.
  const auto spd = chain(300, 0.0, 0.0);
  ASSERT_TRUE(solver.factorize(spd));
  EXPECT_EQ(solver.method(), LinearSolver::Method::SymmetricIndefinite);
  EXPECT_EQ(solver.negative_eigenvalues(), 0);
  EXPECT_LT(relative_error(solver.solve(spd * X), X), 1e-10);
  for (int k = 0; k < 3; ++k) {
    ASSERT_TRUE(solver.factorize(spd));
    EXPECT_TRUE(solver.used_cholesky()) << "factorization " << k;
    EXPECT_LT(relative_error(solver.solve(spd * X), X), 1e-10) << "factorization " << k;
  }
  // And an indefinite K after that falls back to LDLᵀ in the same call.
  ASSERT_TRUE(solver.factorize(K));
  EXPECT_EQ(solver.negative_eigenvalues(), 69);
  EXPECT_LT(relative_error(solver.solve(K * X), X), 1e-10);
}

TEST(LinearSolver, InertiaOfAChainWithOneNegativeEigenvalue) {
  // The smallest eigenvalue 2 - 2 cos(π/301) ≈ 1.09e-4 shifted below zero by 2e-4, the
  // next one 4.36e-4 stays above: exactly one negative eigenvalue, as for a wall just
  // past its pressure limit point under volume control.
  const auto K = chain(300, 2e-4, 0.0);
  const Eigen::MatrixXd X = known_solution(300);
  LinearSolver solver;
  ASSERT_TRUE(solver.factorize(K));
  EXPECT_EQ(solver.negative_eigenvalues(), 1);
  EXPECT_LT(relative_error(solver.solve(K * X), X), 1e-8);
}

TEST(LinearSolver, NonSymmetricUsesLu) {
  const auto K = chain(300, 0.0, 0.3);
  const Eigen::MatrixXd X = known_solution(300);
  LinearSolver solver;
  ASSERT_TRUE(solver.factorize(K));
  EXPECT_EQ(solver.method(), LinearSolver::Method::LU);
  EXPECT_EQ(solver.negative_eigenvalues(), -1);
  EXPECT_LT(relative_error(solver.solve(K * X), X), 1e-10);
}

TEST(LinearSolver, AsymmetryAtRoundOffLevelStillCountsAsSymmetric) {
  // An assembled follower-pressure tangent is symmetric only up to round-off.
  auto K = chain(300, 0.0, 0.0);
  K.coeffRef(10, 11) = std::nextafter(K.coeff(10, 11), 0.0);  // one unit in the last place
  LinearSolver solver;
  ASSERT_TRUE(solver.factorize(K));
  EXPECT_TRUE(solver.used_cholesky());
  K.coeffRef(10, 11) *= 1.0 + 1e-9;  // a real asymmetry: LU
  ASSERT_TRUE(solver.factorize(K));
  EXPECT_EQ(solver.method(), LinearSolver::Method::LU);
}

TEST(LinearSolver, SingularMatrixIsReported) {
  LinearSolver solver;
  // Cholesky fails, then LDLᵀ finds the null pivot.
  EXPECT_FALSE(solver.factorize(with_zero_row_and_column(chain(50, 0.0, 0.0), 20)));
  // Known indefinite now: LDLᵀ directly.
  EXPECT_FALSE(solver.factorize(with_zero_row_and_column(chain(50, 0.5, 0.0), 20)));
}
