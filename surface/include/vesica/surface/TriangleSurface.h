#pragma once
// The triangle surface every surface routine reads and writes: vertices in millimetres in
// ITK/DICOM patient space (LPS), triangles as vertex indices, one region tag per triangle
// (vesica/core/Regions.h codes). Plain Eigen types so that mesh and studies can use it
// without VTK or CGAL.
#include <Eigen/Core>

namespace vesica::surface {

struct TriangleSurface {
  Eigen::MatrixXd V;       // #V by 3, mm, LPS
  Eigen::MatrixXi F;       // #F by 3, vertex indices, counter-clockwise seen from outside
  Eigen::VectorXi region;  // #F, Regions.h codes; empty means "all wall"

  Eigen::Index vertex_count() const { return V.rows(); }
  Eigen::Index triangle_count() const { return F.rows(); }
  // region, or all-wall tags when none were assigned.
  Eigen::VectorXi regions_or_wall() const;
};

// Signed volume enclosed by a closed surface (divergence theorem), mm^3. Positive when the
// triangles are oriented outward.
double enclosed_volume(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
double surface_area(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
// Area-weighted centroid of the surface's enclosed solid (mm).
Eigen::Vector3d volume_centroid(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
// Smallest interior angle of each triangle, degrees (#F).
Eigen::VectorXd triangle_min_angles_deg(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);
// Mean edge length (each triangle's three edges, mm).
double mean_edge_length(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

// Scales the vertices about the enclosed solid's centroid so that the enclosed volume
// becomes target_mm3 (uniform scaling keeps the angles). Returns the scale factor.
double rescale_to_volume(double target_mm3, TriangleSurface& surface);

}  // namespace vesica::surface
