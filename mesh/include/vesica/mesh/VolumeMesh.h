#pragma once
// The mesh handed to the simulation: membrane triangles of the wall (with thickness and
// fiber frames) and, optionally, tetrahedra of the urine sharing the wall's nodes.
#include <Eigen/Core>

namespace vesica::mesh {

struct VolumeMesh {
  Eigen::MatrixXd nodes;         // N x 3, mm; the wall's nodes come first
  Eigen::MatrixXi triangles;     // M x 3 membrane elements, outward oriented
  Eigen::VectorXi tri_region;    // M, vesica::Region codes
  Eigen::VectorXd thickness_mm;  // M
  Eigen::MatrixXd fiber1;        // M x 3
  Eigen::MatrixXd fiber2;        // M x 3
  Eigen::MatrixXi tets;          // K x 4, positive orientation; empty without fluid
};

// Signed volume of one tetrahedron, mm^3 (positive for the orientation used in tets).
double tet_volume_mm3(const VolumeMesh& mesh, Eigen::Index tet);

// Sum of the tetrahedra's volumes, mm^3.
double total_tet_volume_mm3(const VolumeMesh& mesh);

}  // namespace vesica::mesh
