#pragma once
// A dimensionless sparse test matrix for the linear solvers' tests: the 1-D Laplacian
// (2, -1) of size n with `shift` subtracted on the diagonal (past 0 it becomes indefinite)
// and a skew-symmetric coupling `skew` between neighbours (a convection-like term that makes
// it non-symmetric).
#include <vector>

#include <Eigen/Sparse>

namespace vesica::test {

inline Eigen::SparseMatrix<double> chain(int n, double shift, double skew = 0.0) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 - shift);
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0 + skew);
      t.emplace_back(i + 1, i, -1.0 - skew);
    }
  }
  Eigen::SparseMatrix<double> K(n, n);
  K.setFromTriplets(t.begin(), t.end());
  K.makeCompressed();
  return K;
}

}  // namespace vesica::test
