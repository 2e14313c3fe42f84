#pragma once
// A closed triangle surface as the file formats carry it between stages: vertices in
// millimetres (patient LPS), triangles as vertex indices, one region tag per triangle
// (vesica/core/Regions.h codes) or none at all. Plain Eigen arrays; each stage converts to
// its own working type.
#include <Eigen/Core>

namespace vesica::io {

struct TaggedSurface {
  Eigen::MatrixXd points_mm;  // N x 3, mm
  Eigen::MatrixXi triangles;  // M x 3, zero-based
  Eigen::VectorXi region;     // M Regions.h codes, or empty: the file has no region tags

  bool has_regions() const { return region.size() > 0 && region.size() == triangles.rows(); }
};

// Centroid of each triangle (M x 3, mm).
Eigen::MatrixXd triangle_centroids(const Eigen::MatrixXd& points_mm,
                                   const Eigen::MatrixXi& triangles);

}  // namespace vesica::io
