#include "solver/PreconditionedGmres.h"

#include <cmath>

namespace vesica::simulate {
namespace {

// The Givens rotation (c, s) that zeroes b in (a, b).
void givens(double a, double b, double& c, double& s) {
  const double r = std::hypot(a, b);
  c = r > 0.0 ? a / r : 1.0;
  s = r > 0.0 ? b / r : 0.0;
}

}  // namespace

GmresResult preconditioned_gmres(
    const Eigen::SparseMatrix<double>& K,
    const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& precondition,
    const Eigen::VectorXd& b, double tolerance, int max_iterations, Eigen::VectorXd& x) {
  const Eigen::Index n = b.size();
  const int m = std::max(1, max_iterations);
  if (x.size() != n) x = Eigen::VectorXd::Zero(n);
  const Eigen::VectorXd r0 = b - K * x;
  GmresResult result;
  const double goal = tolerance * b.norm(), beta = r0.norm();
  if (beta <= goal) {
    result.converged = true;
    return result;
  }
  // Arnoldi basis V of K M⁻¹, its preconditioned vectors Z = M⁻¹ V (kept, so that x needs
  // no further solve), the Hessenberg matrix H reduced to triangular by rotations (c, s),
  // and g, the rotated right-hand side whose last entry is the residual norm.
  Eigen::MatrixXd V(n, m + 1), Z(n, m), H = Eigen::MatrixXd::Zero(m + 1, m);
  Eigen::VectorXd c(m), s(m), g = Eigen::VectorXd::Zero(m + 1);
  g(0) = beta;
  V.col(0) = r0 / beta;
  int k = 0;
  while (k < m) {
    Z.col(k) = precondition(V.col(k));
    Eigen::VectorXd w = K * Z.col(k);
    for (int i = 0; i <= k; ++i) {  // modified Gram–Schmidt
      H(i, k) = w.dot(V.col(i));
      w -= H(i, k) * V.col(i);
    }
    H(k + 1, k) = w.norm();
    const bool breakdown = !(H(k + 1, k) > 1e-300);  // the exact solution is in the space
    if (!breakdown) V.col(k + 1) = w / H(k + 1, k);
    for (int i = 0; i < k; ++i) {
      const double h = c(i) * H(i, k) + s(i) * H(i + 1, k);
      H(i + 1, k) = -s(i) * H(i, k) + c(i) * H(i + 1, k);
      H(i, k) = h;
    }
    givens(H(k, k), H(k + 1, k), c(k), s(k));
    H(k, k) = c(k) * H(k, k) + s(k) * H(k + 1, k);
    H(k + 1, k) = 0.0;
    g(k + 1) = -s(k) * g(k);
    g(k) = c(k) * g(k);
    ++k;
    if (std::abs(g(k)) <= goal || breakdown) {
      result.converged = std::isfinite(g(k));
      break;
    }
  }
  result.iterations = k;
  const Eigen::VectorXd y = H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
  x += Z.leftCols(k) * y;
  return result;
}

}  // namespace vesica::simulate
