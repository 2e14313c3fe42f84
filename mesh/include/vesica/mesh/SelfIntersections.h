#pragma once
// Pairs of triangles that intersect other than along shared edges or corners (CGAL).
#include <cstddef>
#include <optional>

#include <Eigen/Core>

namespace vesica::mesh {

// points N x 3, triangles M x 3. Empty when the triangles do not form an oriented
// 2-manifold (possibly with holes), which CGAL's halfedge mesh needs.
std::optional<std::size_t> count_self_intersecting_pairs(const Eigen::MatrixXd& points,
                                                         const Eigen::MatrixXi& triangles);

}  // namespace vesica::mesh
