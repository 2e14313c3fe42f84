#pragma once
// Transfer of nodal fields between two tetrahedral meshes of the same domain (the urine
// before and after remeshing, docs/navier-stokes.md §1): P1 interpolation in the old
// tetrahedra, which is exact for fields linear in space. Positions in m.
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace vesica::simulate::fluid {

// Where one point lies in the old mesh: its tetrahedron and barycentric coordinates.
struct TetLocation {
  int tet = -1;
  Eigen::Vector4d weights = Eigen::Vector4d::Zero();  // sum to 1
};

// Locates each point in the tetrahedra at positions x. A point outside every tetrahedron
// (by round-off at the boundary) takes the one whose least barycentric coordinate is the
// least negative. Throws std::invalid_argument when there are no tetrahedra.
std::vector<TetLocation> locate_points(const std::vector<Eigen::Vector3d>& x,
                                       const std::vector<std::array<int, 4>>& tets,
                                       const std::vector<Eigen::Vector3d>& points);

// Interpolates a node-major field (components per node, e.g. kDofsPerNode) of the old
// mesh at the located points; returns components × points.size() values.
Eigen::VectorXd interpolate_field(const Eigen::VectorXd& field, int components,
                                  const std::vector<std::array<int, 4>>& tets,
                                  const std::vector<TetLocation>& locations);

}  // namespace vesica::simulate::fluid
