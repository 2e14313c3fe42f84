#pragma once
// Urine tetrahedra filling the wall at its current positions (remeshing,
// docs/navier-stokes.md §1), built by vesica-mesh's gmsh cavity mesher.
#include <vector>

#include <Eigen/Dense>

#include "vesica/simulate/WallModel.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

// Nodes 0..N−1 are exactly x_wall (m, one per wall node), then the interior nodes; the
// tetrahedra are positively oriented. max_size_mm: longest tet edge (0 = the wall's mean
// edge at x_wall). Throws vesica::Error when gmsh fails (e.g. a self-intersecting wall).
FluidMesh cavity_tetrahedra(const WallModel& wall, const std::vector<Eigen::Vector3d>& x_wall,
                            double max_size_mm = 0.0);

}  // namespace vesica::simulate::fluid
