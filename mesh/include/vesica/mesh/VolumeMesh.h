#pragma once
// The mesh handed to the simulation: membrane triangles of the wall (with thickness and
// fiber frames) and, optionally, tetrahedra of the urine sharing the wall's nodes.
#include <Eigen/Core>

#include "vesica/io/VolumeMesh.h"

namespace vesica::mesh {

// The type of the files that carry it (vesica/io/VolumeMesh.h).
using VolumeMesh = io::VolumeMesh;

// Signed volume of one tetrahedron, mm^3 (positive for the orientation used in tets).
double tet_volume_mm3(const VolumeMesh& mesh, Eigen::Index tet);

// Sum of the tetrahedra's volumes, mm^3.
double total_tet_volume_mm3(const VolumeMesh& mesh);

}  // namespace vesica::mesh
