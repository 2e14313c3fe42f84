// GMRES preconditioned by the factorization of a nearby matrix (the reuse of a Newton
// tangent's factorization, NewtonOptions.h): it must reproduce a known solution x from
// b = K x to its tolerance, in one solve when the preconditioner is K's own factorization,
// in a few when it is a slightly different matrix's (definite or indefinite), and report
// failure when the preconditioner is too far from K. Dimensionless test matrices.
#include <gtest/gtest.h>

#include <vector>

#include "ChainMatrix.h"
#include "solver/LinearSolver.h"
#include "solver/PreconditionedGmres.h"

using namespace vesica::simulate;
using vesica::test::chain;

namespace {

Eigen::VectorXd known_solution(int n) {
  Eigen::VectorXd x(n);
  for (int i = 0; i < n; ++i) x(i) = std::sin(0.1 * i) + 0.01 * i;
  return x;
}

struct Solved {
  GmresResult result;
  double relative_error = 0.0, relative_residual = 0.0;
};

Solved solve_with(const Eigen::SparseMatrix<double>& K, const Eigen::SparseMatrix<double>& M,
                  double tolerance, int max_iterations) {
  LinearSolver lu;
  EXPECT_TRUE(lu.factorize(M));
  const Eigen::VectorXd x_true = known_solution(static_cast<int>(K.rows()));
  const Eigen::VectorXd b = K * x_true;
  Eigen::VectorXd x;
  Solved s;
  s.result = preconditioned_gmres(
      K, [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return lu.solve(v); }, b, tolerance,
      max_iterations, x);
  s.relative_error = (x - x_true).norm() / x_true.norm();
  s.relative_residual = (b - K * x).norm() / b.norm();
  return s;
}

}  // namespace

TEST(PreconditionedGmres, ExactPreconditionerSolvesInOneStep) {
  const auto K = chain(300, 0.0);
  const Solved s = solve_with(K, K, 1e-10, 8);
  EXPECT_TRUE(s.result.converged);
  EXPECT_EQ(s.result.iterations, 1);
  EXPECT_LT(s.relative_error, 1e-8);
}

TEST(PreconditionedGmres, NearbyDefiniteMatrixMeetsTheTolerance) {
  // A well-conditioned chain whose diagonal is 1.25 % away from the factorized matrix's.
  const auto K = chain(300, -2.05), M = chain(300, -2.0);
  const Solved s = solve_with(K, M, 1e-10, 20);
  EXPECT_TRUE(s.result.converged);
  EXPECT_GT(s.result.iterations, 1);
  EXPECT_LE(s.result.iterations, 20);
  EXPECT_LT(s.relative_residual, 2e-10);
}

TEST(PreconditionedGmres, NearbyIndefiniteUnsymmetricMatrixMeetsTheTolerance) {
  // Past a limit point (negative eigenvalues) and with a skew coupling, as LU sees it.
  const auto K = chain(200, 0.5, 0.02), M = chain(200, 0.49, 0.0);
  const Solved s = solve_with(K, M, 1e-10, 30);
  EXPECT_TRUE(s.result.converged);
  EXPECT_LT(s.relative_residual, 2e-10);
}

TEST(PreconditionedGmres, FarPreconditionerReportsFailure) {
  // The identity's neighbour for a Laplacian: far too few iterations for 1e-10.
  Eigen::SparseMatrix<double> I(200, 200);
  I.setIdentity();
  const Solved s = solve_with(chain(200, 0.0), I, 1e-10, 3);
  EXPECT_FALSE(s.result.converged);
  EXPECT_EQ(s.result.iterations, 3);
}
