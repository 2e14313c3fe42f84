#include "vesica/mesh/SurfaceMesh.h"

#include <Eigen/Geometry>

namespace vesica::mesh {

namespace {
Eigen::Vector3d corner(const SurfaceMesh& s, Eigen::Index t, int k) {
  return s.points.row(s.triangles(t, k)).transpose();
}
}  // namespace

double enclosed_volume_mm3(const SurfaceMesh& surface) {
  // Sum of signed volumes of the tetrahedra (origin, triangle); exact for any origin
  // when the surface is closed. Centring on the first point limits round-off.
  const Eigen::Vector3d o =
      surface.points.rows() ? Eigen::Vector3d(surface.points.row(0)) : Eigen::Vector3d::Zero();
  double six_v = 0.0;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    six_v += (corner(surface, t, 0) - o)
                 .dot((corner(surface, t, 1) - o).cross(corner(surface, t, 2) - o));
  }
  return six_v / 6.0;
}

void flip_orientation(SurfaceMesh& surface) {
  surface.triangles.col(1).swap(surface.triangles.col(2));
}

Eigen::MatrixXd triangle_normals(const SurfaceMesh& surface) {
  Eigen::MatrixXd n(surface.triangles.rows(), 3);
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    const Eigen::Vector3d c = (corner(surface, t, 1) - corner(surface, t, 0))
                                  .cross(corner(surface, t, 2) - corner(surface, t, 0));
    const double len = c.norm();
    n.row(t) = len > 0 ? Eigen::Vector3d(c / len) : Eigen::Vector3d::Zero();
  }
  return n;
}

Eigen::VectorXd triangle_areas_mm2(const SurfaceMesh& surface) {
  Eigen::VectorXd a(surface.triangles.rows());
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    a(t) = 0.5 * (corner(surface, t, 1) - corner(surface, t, 0))
                     .cross(corner(surface, t, 2) - corner(surface, t, 0))
                     .norm();
  }
  return a;
}

double mean_edge_length_mm(const SurfaceMesh& surface) {
  double sum = 0.0;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    for (int k = 0; k < 3; ++k)
      sum += (corner(surface, t, k) - corner(surface, t, (k + 1) % 3)).norm();
  return surface.triangles.rows() ? sum / (3.0 * surface.triangles.rows()) : 0.0;
}

}  // namespace vesica::mesh
