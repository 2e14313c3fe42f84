#pragma once
// The mesh passed from the mesh stage to the simulation (.msh and .vtu, MshFile.h and
// VtuFile.h): membrane triangles of the wall with thickness and fiber frames and,
// optionally, tetrahedra of the urine sharing the wall's nodes. Millimetres.
#include <Eigen/Core>

namespace vesica::io {

struct VolumeMesh {
  Eigen::MatrixXd nodes;         // N x 3, mm; the wall's nodes come first
  Eigen::MatrixXi triangles;     // M x 3 membrane elements, outward oriented
  Eigen::VectorXi tri_region;    // M, vesica::Region codes
  Eigen::VectorXd thickness_mm;  // M, or empty when a file had none
  Eigen::MatrixXd fiber1;        // M x 3 unit, in the triangle's plane; or 0 rows
  Eigen::MatrixXd fiber2;        // M x 3 unit, in plane, normal x fiber1; or 0 rows
  Eigen::MatrixXi tets;          // K x 4, positive orientation; empty without fluid
};

}  // namespace vesica::io
