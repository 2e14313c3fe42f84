#pragma once
// GMRES on K x = b, right-preconditioned by the exact solve of a nearby matrix: the last
// factorized Newton tangent. While the tangent changes little from one iteration (or step)
// to the next, K M⁻¹ is close to the identity and a few preconditioner solves give the
// Newton increment to the asked accuracy, at a fraction of a new factorization's cost
// (inexact Newton: Newton's convergence is kept as long as the linear residual is small
// next to the nonlinear one). Right preconditioning minimizes the true residual |b − K x|,
// so its test means what it says. No restart: when max_iterations do not suffice the
// tangent has moved too far and a new factorization is cheaper (the caller's fallback).
#include <functional>

#include <Eigen/Dense>
#include <Eigen/Sparse>

namespace vesica::simulate {

struct GmresResult {
  bool converged = false;
  int iterations = 0;  // preconditioner solves
};

// x with |b − K x| ≤ tolerance |b| within max_iterations solves by `precondition`
// (y ↦ M⁻¹ y); otherwise x is the best found and converged is false. x on entry: the
// initial guess when it has b's size (a solution of a nearby system), else zero.
GmresResult preconditioned_gmres(
    const Eigen::SparseMatrix<double>& K,
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
    const Eigen::VectorXd& b, double tolerance, int max_iterations, Eigen::VectorXd& x);

}  // namespace vesica::simulate
