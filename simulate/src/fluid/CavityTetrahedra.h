#pragma once
// Urine tetrahedra filling the wall at its current positions (remeshing,
// docs/navier-stokes.md §1), built by vesica-mesh's gmsh cavity mesher.
#include <vector>

#include <Eigen/Dense>

#include "vesica/simulate/fluid/FluidMesh.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate::fluid {

// Nodes 0..N−1 are exactly x_wall (m, one per wall node), then the interior nodes; the
// tetrahedra are positively oriented. max_size_mm: longest tet edge (0 = the wall's mean
// edge at x_wall). Throws vesica::Error when gmsh fails (e.g. a self-intersecting wall).
FluidMesh cavity_tetrahedra(const WallModel& wall, const std::vector<Eigen::Vector3d>& x_wall,
                            double max_size_mm = 0.0);

// The same with about `target` tetrahedra (within the relative `tolerance`), so that a
// remesh keeps the resolution of the mesh it replaces: the longest edge is searched from
// size_mm (≤ 0: the wall's mean edge) by secant steps on log(count) against log(size), a
// few gmsh runs at most; size_mm returns the size of the mesh returned (the closest
// count found when none is within tolerance).
FluidMesh cavity_tetrahedra_of_count(const WallModel& wall,
                                     const std::vector<Eigen::Vector3d>& x_wall, std::size_t target,
                                     double tolerance, double& size_mm);

}  // namespace vesica::simulate::fluid
