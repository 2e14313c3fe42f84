#pragma once
// A triangulated sphere for verification and benchmarks: the octahedron with each face
// split into n² triangles, projected onto the sphere (8 n² triangles). Its six axis points
// are nodes, which lets the tests remove rigid-body motion without restraining the
// radial expansion.
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// Radius and thickness in m; every triangle is "wall" (region 1).
WallModel sphere_wall(double radius, double thickness, int n);

// Holds x,y at both poles (0,0,±R) and y,z at (R,0,0): six constraints that stop
// translation and rotation of a sphere centred at the origin and leave it free to grow.
void fix_sphere_rigid_modes(WallModel& wall);

}  // namespace vesica::simulate
