#pragma once
// Boundary triangles of a tetrahedral mesh with their outward side, and the quantities
// measured on them: volume flow rate through a set of faces (m³/s) and wall shear
// stress (Pa). Outward = away from the one tetrahedron that owns the face.
#include <array>
#include <map>
#include <vector>

#include <Eigen/Dense>

#include "fluid/FluidModel.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

class BoundaryFaces {
 public:
  // Keeps a reference: the mesh must outlive this object.
  explicit BoundaryFaces(const FluidMesh& mesh);

  // All boundary triangles, oriented so that their right-hand normal points outward.
  const std::vector<std::array<int, 3>>& faces() const { return faces_; }
  // The tetrahedron owning a boundary triangle (any orientation); throws
  // std::invalid_argument when the triangle is not on the boundary.
  int owner(const std::array<int, 3>& face) const;
  const FluidMesh& mesh() const { return mesh_; }
  // Area-weighted outward normal (|n| = area, m²) of a boundary triangle.
  Eigen::Vector3d area_normal(const std::array<int, 3>& face) const;
  // The same with the nodes at `positions` (a moved mesh with the same connectivity).
  Eigen::Vector3d area_normal(const std::array<int, 3>& face,
                              const std::vector<Eigen::Vector3d>& positions) const;

 private:
  const FluidMesh& mesh_;
  std::vector<std::array<int, 3>> faces_;
  std::map<std::array<int, 3>, int> owner_;  // sorted node triple -> tet
};

// Q = ∫ u·n dA over the faces (outward positive), m³/s; state as in FluidMesh.h.
double flow_rate(const BoundaryFaces& boundary, const std::vector<std::array<int, 3>>& faces,
                 const Eigen::VectorXd& state);

// Wall shear stress (I − n⊗n) σ n on each face, σ = −pI + 2μ ε(u) of its tetrahedron, Pa.
std::vector<Eigen::Vector3d> wall_shear_stress(const BoundaryFaces& boundary,
                                               const std::vector<std::array<int, 3>>& faces,
                                               const FluidProperties& fluid,
                                               const Eigen::VectorXd& state);

}  // namespace vesica::simulate::fluid
