#pragma once
// The urine domain as linear tetrahedra (the input of a level-2 cystometry) and the layout
// of the urine state on it (the fields written to fluid.pvd). Positions in m.
// Unknowns are node-major: dof 4 i + k is velocity component k (m/s) of node i for
// k < 3, and its pressure (Pa) for k = 3; with a urethra outlet, one more dof at the end:
// the outlet pressure p_out (Pa).
#include <array>
#include <vector>

#include <Eigen/Dense>

namespace vesica::simulate::fluid {

struct FluidMesh {
  std::vector<Eigen::Vector3d> nodes;    // m
  std::vector<std::array<int, 4>> tets;  // either orientation
};

constexpr Eigen::Index kDofsPerNode = 4;

}  // namespace vesica::simulate::fluid
