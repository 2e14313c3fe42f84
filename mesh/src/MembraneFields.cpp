#include "vesica/mesh/MembraneFields.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace vesica::mesh {

namespace {

// Below this sine of the angle between direction and plane, the projection is noise.
constexpr double kMinProjection = 1e-3;

double thickness_of(int region, const MembraneOptions& options) {
  const auto it = options.thickness_by_region_mm.find(static_cast<Region>(region));
  return it == options.thickness_by_region_mm.end() ? options.thickness_mm : it->second;
}

}  // namespace

Eigen::Vector3d long_axis(const SurfaceMesh& surface) {
  const Eigen::VectorXd areas = triangle_areas_mm2(surface);
  Eigen::MatrixXd centroids(surface.triangles.rows(), 3);
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t)
    centroids.row(t) =
        (surface.points.row(surface.triangles(t, 0)) + surface.points.row(surface.triangles(t, 1)) +
         surface.points.row(surface.triangles(t, 2))) /
        3.0;
  const double total = areas.sum();
  const Eigen::RowVector3d mean = (areas.transpose() * centroids) / total;
  const Eigen::MatrixXd centred = centroids.rowwise() - mean;
  const Eigen::Matrix3d covariance = centred.transpose() * areas.asDiagonal() * centred / total;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  return eigen.eigenvectors().col(2).normalized();  // eigenvalues ascend
}

MembraneFields membrane_fields(const SurfaceMesh& surface, const MembraneOptions& options) {
  const Eigen::Index m = surface.triangles.rows();
  const Eigen::MatrixXd normals = triangle_normals(surface);
  const Eigen::Vector3d d = options.fiber_direction.normalized();
  MembraneFields f;
  f.thickness_mm.resize(m);
  f.fiber1.resize(m, 3);
  f.fiber2.resize(m, 3);
  for (Eigen::Index t = 0; t < m; ++t) {
    f.thickness_mm(t) = thickness_of(surface.region(t), options);
    const Eigen::Vector3d n = normals.row(t).transpose();
    Eigen::Vector3d a = d - d.dot(n) * n;
    if (a.norm() < kMinProjection) {
      const Eigen::Vector3d edge =
          surface.points.row(surface.triangles(t, 1)) - surface.points.row(surface.triangles(t, 0));
      a = edge - edge.dot(n) * n;
    }
    a.normalize();
    f.fiber1.row(t) = a.transpose();
    f.fiber2.row(t) = n.cross(a).normalized().transpose();
  }
  return f;
}

}  // namespace vesica::mesh
