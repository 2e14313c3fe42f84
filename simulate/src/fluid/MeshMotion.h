#pragma once
// ALE mesh motion (docs/navier-stokes.md §1): the displacement of the interior nodes of
// the urine mesh as the discrete harmonic extension of the displacement given on the
// wall (and cap) nodes, ∇·(k ∇d) = 0 per component, with k = 1/V_e of the reference
// tetrahedra by default so that small elements (near the wall) deform least. The
// Laplacian is factorized once per reference mesh. Displacements and positions in m.
#include <memory>
#include <vector>

#include <Eigen/Dense>

#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

struct MeshMotionOptions {
  bool stiffen_small_elements = true;  // k = 1/V_e; false: k = 1 (reproduces linear d exactly)
};

class HarmonicMeshMotion {
 public:
  // prescribed[i]: node i's displacement is given (wall, caps). Keeps a reference to the
  // mesh. Throws std::invalid_argument when no node is prescribed.
  HarmonicMeshMotion(const FluidMesh& reference, const std::vector<bool>& prescribed,
                     MeshMotionOptions options = {});
  ~HarmonicMeshMotion();

  // displacement: one per node, read only at prescribed nodes; returns the displacement
  // of every node (prescribed ones unchanged).
  std::vector<Eigen::Vector3d> extend(const std::vector<Eigen::Vector3d>& displacement) const;

 private:
  struct Factorization;
  const FluidMesh& mesh_;
  std::vector<bool> prescribed_;
  std::vector<int> free_index_;  // node -> row of the free system, −1 when prescribed
  std::unique_ptr<Factorization> factorization_;
};

}  // namespace vesica::simulate::fluid
