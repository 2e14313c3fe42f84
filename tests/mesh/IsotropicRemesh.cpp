// The only test translation unit that instantiates CGAL.
#include "IsotropicRemesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <array>
#include <vector>

namespace vesica::test {

mesh::SurfaceMesh isotropic_remesh(const mesh::SurfaceMesh& surface, double edge_mm,
                                   int iterations) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
  namespace PMP = CGAL::Polygon_mesh_processing;
  std::vector<Kernel::Point_3> points;
  for (Eigen::Index i = 0; i < surface.points.rows(); ++i)
    points.emplace_back(surface.points(i, 0), surface.points(i, 1), surface.points(i, 2));
  std::vector<std::array<std::size_t, 3>> soup(surface.triangles.rows());
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k) soup[t][k] = static_cast<std::size_t>(surface.triangles(t, k));
  Mesh m;
  PMP::polygon_soup_to_polygon_mesh(points, soup, m);
  PMP::isotropic_remeshing(CGAL::faces(m), edge_mm, m,
                           CGAL::parameters::number_of_iterations(iterations));
  m.collect_garbage();
  std::vector<Kernel::Point_3> out_points;
  std::vector<std::vector<std::size_t>> out_faces;
  PMP::polygon_mesh_to_polygon_soup(m, out_points, out_faces);
  mesh::SurfaceMesh s;
  s.points.resize(static_cast<Eigen::Index>(out_points.size()), 3);
  for (std::size_t i = 0; i < out_points.size(); ++i)
    s.points.row(static_cast<Eigen::Index>(i)) << out_points[i].x(), out_points[i].y(),
        out_points[i].z();
  s.triangles.resize(static_cast<Eigen::Index>(out_faces.size()), 3);
  for (std::size_t t = 0; t < out_faces.size(); ++t)
    for (int k = 0; k < 3; ++k)
      s.triangles(static_cast<Eigen::Index>(t), k) = static_cast<int>(out_faces[t][k]);
  s.region = Eigen::VectorXi::Constant(s.triangles.rows(), 1);
  return s;
}

}  // namespace vesica::test
