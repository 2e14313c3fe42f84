#pragma once
// Edge topology of a triangle list, counted without building a half-edge mesh (which
// cannot even hold a non-manifold edge): what a bad input is reported with.
#include <Eigen/Core>

namespace vesica::surface {

struct EdgeTopology {
  int boundary_edges = 0;      // edges used by one triangle
  int non_manifold_edges = 0;  // edges used by more than two triangles
  int holes = 0;               // closed loops of boundary edges
  int inconsistent_edges = 0;  // two triangles traversing a shared edge the same way
  bool closed() const { return boundary_edges == 0; }
  bool edge_manifold() const { return non_manifold_edges == 0; }
};

EdgeTopology edge_topology(const Eigen::MatrixXi& F);

}  // namespace vesica::surface
