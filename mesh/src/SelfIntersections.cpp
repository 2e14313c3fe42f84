// The only translation unit that instantiates CGAL (it is heavy to compile).
#include "vesica/mesh/SelfIntersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <iterator>
#include <vector>

namespace vesica::mesh {

std::optional<std::size_t> count_self_intersecting_pairs(const Eigen::MatrixXd& points,
                                                         const Eigen::MatrixXi& triangles) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  namespace PMP = CGAL::Polygon_mesh_processing;

  std::vector<Kernel::Point_3> soup_points;
  soup_points.reserve(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    soup_points.emplace_back(points(i, 0), points(i, 1), points(i, 2));
  std::vector<std::array<std::size_t, 3>> soup_faces(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) soup_faces[t][k] = static_cast<std::size_t>(triangles(t, k));

  if (!PMP::is_polygon_soup_a_polygon_mesh(soup_faces)) return std::nullopt;
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(soup_points, soup_faces, mesh);
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  PMP::self_intersections(mesh, std::back_inserter(pairs));
  return pairs.size();
}

}  // namespace vesica::mesh
