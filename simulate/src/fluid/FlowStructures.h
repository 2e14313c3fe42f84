#pragma once
// Vortex structures of the urine flow, per tetrahedron of a P1 velocity field (constant
// gradient G = ∇u in each; docs/physics.md §4): the vorticity ω = ∇ × u (1/s) and the
// Q-criterion Q = ½ (‖W‖² − ‖S‖²) (1/s²), with S and W the symmetric and antisymmetric
// parts of G. Q > 0 where rotation dominates strain: the cores of the vortices that the
// inflow jets roll up while filling (Hunt, Wray and Moin's criterion).
#include <vector>

#include <Eigen/Dense>

#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

struct TetVortexMeasures {
  Eigen::Vector3d vorticity = Eigen::Vector3d::Zero();  // 1/s
  double q_criterion = 0.0;                             // 1/s²
};

// Of a velocity gradient G(i, j) = ∂u_i/∂x_j (1/s).
TetVortexMeasures vortex_measures(const Eigen::Matrix3d& velocity_gradient);

// One per tetrahedron of mesh (positions in m), from the velocities of state (layout as in
// FluidMesh.h, m/s). A degenerate tetrahedron gets zeros.
std::vector<TetVortexMeasures> tet_vortex_measures(const FluidMesh& mesh,
                                                   const Eigen::VectorXd& state);

}  // namespace vesica::simulate::fluid
