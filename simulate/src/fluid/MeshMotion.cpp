#include "fluid/MeshMotion.h"

#include <stdexcept>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include "fluid/StabilizedTet.h"

namespace vesica::simulate::fluid {

struct HarmonicMeshMotion::Factorization {
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt;  // free-free block, SPD
  Eigen::SparseMatrix<double> coupling;                     // free rows, prescribed columns
};

HarmonicMeshMotion::HarmonicMeshMotion(const FluidMesh& reference,
                                       const std::vector<bool>& prescribed,
                                       MeshMotionOptions options)
    : mesh_(reference),
      prescribed_(prescribed),
      free_index_(reference.nodes.size(), -1),
      factorization_(std::make_unique<Factorization>()) {
  const int n = static_cast<int>(reference.nodes.size());
  int free_count = 0;
  for (int i = 0; i < n; ++i)
    if (!prescribed[i]) free_index_[i] = free_count++;
  if (free_count == n) throw std::invalid_argument("mesh motion needs prescribed nodes");

  std::vector<Eigen::Triplet<double>> free_free, free_fixed;
  for (const auto& tet : reference.tets) {
    std::array<Eigen::Vector3d, 4> x;
    for (int a = 0; a < 4; ++a) x[a] = reference.nodes[tet[a]];
    Eigen::Matrix<double, 4, 3> dN;
    double volume = 0.0;
    tet_gradients(x, dN, volume);
    // ∫ k ∇N_a·∇N_b = k V ∇N_a·∇N_b; with k = 1/V every element counts alike.
    const double weight = options.stiffen_small_elements ? 1.0 : volume;
    const Eigen::Matrix4d k = weight * dN * dN.transpose();
    for (int a = 0; a < 4; ++a) {
      const int row = free_index_[tet[a]];
      if (row < 0) continue;
      for (int b = 0; b < 4; ++b) {
        const int col = free_index_[tet[b]];
        if (col >= 0)
          free_free.emplace_back(row, col, k(a, b));
        else
          free_fixed.emplace_back(row, tet[b], k(a, b));
      }
    }
  }
  Eigen::SparseMatrix<double> A(free_count, free_count);
  A.setFromTriplets(free_free.begin(), free_free.end());
  factorization_->coupling.resize(free_count, n);
  factorization_->coupling.setFromTriplets(free_fixed.begin(), free_fixed.end());
  factorization_->ldlt.compute(A);
  if (factorization_->ldlt.info() != Eigen::Success)
    throw std::runtime_error("mesh-motion Laplacian is singular (a node without neighbours?)");
}

HarmonicMeshMotion::~HarmonicMeshMotion() = default;

std::vector<Eigen::Vector3d> HarmonicMeshMotion::extend(
    const std::vector<Eigen::Vector3d>& displacement) const {
  const int n = static_cast<int>(mesh_.nodes.size());
  Eigen::MatrixXd given = Eigen::MatrixXd::Zero(n, 3);
  for (int i = 0; i < n; ++i)
    if (prescribed_[i]) given.row(i) = displacement[i].transpose();
  const Eigen::MatrixXd free = factorization_->ldlt.solve(-(factorization_->coupling * given));
  std::vector<Eigen::Vector3d> result(n);
  for (int i = 0; i < n; ++i)
    result[i] = prescribed_[i] ? displacement[i] : Eigen::Vector3d(free.row(free_index_[i]));
  return result;
}

}  // namespace vesica::simulate::fluid
