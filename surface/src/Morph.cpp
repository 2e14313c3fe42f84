#include "vesica/surface/Morph.h"

#include <cmath>

#include <Eigen/Eigenvalues>

#include "vesica/core/Error.h"

namespace vesica::surface {

Eigen::Matrix3d principal_axes(const Eigen::MatrixXd& V) {
  const Eigen::MatrixXd centred = V.rowwise() - V.colwise().mean();
  const Eigen::Matrix3d covariance =
      centred.transpose() * centred / std::max<Eigen::Index>(1, V.rows());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  // Eigen sorts eigenvalues ascending; longest axis first.
  return solver.eigenvectors().rowwise().reverse();
}

void morph_principal_axes(const Eigen::Vector3d& stretch, TriangleSurface& surface) {
  if (!(stretch.minCoeff() > 0)) usage_error("--morph factors must be positive");
  const double volume = enclosed_volume(surface.V, surface.F);
  const Eigen::Vector3d s = stretch / std::cbrt(stretch.prod());
  const Eigen::Matrix3d axes = principal_axes(surface.V);
  const Eigen::Matrix3d map = axes * s.asDiagonal() * axes.transpose();
  const Eigen::RowVector3d c = volume_centroid(surface.V, surface.F).transpose();
  surface.V = ((surface.V.rowwise() - c) * map.transpose()).rowwise() + c;
  rescale_to_volume(volume, surface);
}

}  // namespace vesica::surface
