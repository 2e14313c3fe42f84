#pragma once
// A closed triangle surface of the bladder in millimetres: the membrane elements of the
// wall and the boundary of the urine. Plain Eigen arrays so that every stage can use it.
#include <Eigen/Core>

namespace vesica::mesh {

struct SurfaceMesh {
  Eigen::MatrixXd points;     // N x 3, mm
  Eigen::MatrixXi triangles;  // M x 3, zero-based point indices
  Eigen::VectorXi region;     // M, vesica::Region codes
};

// Volume enclosed by a closed surface (divergence theorem), mm^3; positive when the
// triangles are oriented outwards.
double enclosed_volume_mm3(const SurfaceMesh& surface);

// Reverses every triangle (outward <-> inward).
void flip_orientation(SurfaceMesh& surface);

// Unit normals (M x 3) and areas (M) of the triangles.
Eigen::MatrixXd triangle_normals(const SurfaceMesh& surface);
Eigen::VectorXd triangle_areas_mm2(const SurfaceMesh& surface);

// Mean edge length, mm.
double mean_edge_length_mm(const SurfaceMesh& surface);

}  // namespace vesica::mesh
