#include "vesica/io/TaggedSurface.h"

namespace vesica::io {

Eigen::MatrixXd triangle_centroids(const Eigen::MatrixXd& points_mm,
                                   const Eigen::MatrixXi& triangles) {
  Eigen::MatrixXd c(triangles.rows(), 3);
  for (Eigen::Index f = 0; f < triangles.rows(); ++f)
    c.row(f) = (points_mm.row(triangles(f, 0)) + points_mm.row(triangles(f, 1)) +
                points_mm.row(triangles(f, 2))) /
               3.0;
  return c;
}

}  // namespace vesica::io
