#include "vesica/mesh/VolumeMesh.h"

#include <Eigen/Geometry>

namespace vesica::mesh {

double tet_volume_mm3(const VolumeMesh& mesh, Eigen::Index tet) {
  const Eigen::Vector3d a = mesh.nodes.row(mesh.tets(tet, 0));
  const Eigen::Vector3d b = mesh.nodes.row(mesh.tets(tet, 1));
  const Eigen::Vector3d c = mesh.nodes.row(mesh.tets(tet, 2));
  const Eigen::Vector3d d = mesh.nodes.row(mesh.tets(tet, 3));
  return (b - a).dot((c - a).cross(d - a)) / 6.0;
}

double total_tet_volume_mm3(const VolumeMesh& mesh) {
  double sum = 0.0;
  for (Eigen::Index t = 0; t < mesh.tets.rows(); ++t) sum += tet_volume_mm3(mesh, t);
  return sum;
}

}  // namespace vesica::mesh
