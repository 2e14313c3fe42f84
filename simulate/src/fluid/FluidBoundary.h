#pragma once
// Boundary conditions of the urine flow (level 2) on the tetrahedra of FluidMesh.h and the
// moving-mesh frame of a step. SI units.
#include <array>
#include <vector>

#include <Eigen/Dense>

#include "cavity/UrethraLaw.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

// Velocity prescribed on some components of one node (no-slip: all three, zero).
struct VelocityCondition {
  int node = 0;
  std::array<bool, 3> component{true, true, true};
  Eigen::Vector3d value = Eigen::Vector3d::Zero();  // m/s
};

// A boundary triangle carrying the traction -p̄ n (n outward from the fluid).
struct PressureFace {
  std::array<int, 3> nodes{};  // any orientation; the outward side is found from the mesh
  double pressure = 0.0;       // p̄, Pa
};

// The open urethra outlet (docs/physics.md §5): traction −p n on the outlet faces with
// p = p_out + ρ g·(x − x_ref) (p_out at the patch centroid x_ref, hydrostatic over the
// patch), p_out one extra unknown (the last dof of the state) tied to the outflow
// Q = ∫ u·n dA by the law in pressure form, p_out − p_close = R1 Q + R2 Q|Q| (rigid)
// (UrethraLaw::pressure_drop). While the urethra is closed (filling, or p below p_open)
// the caller treats the outlet faces as wall instead.
struct UrethraOutlet {
  std::vector<std::array<int, 3>> faces;
  UrethraLaw law;
};

struct FluidBoundary {
  std::vector<VelocityCondition> velocity;
  std::vector<PressureFace> pressure_faces;
  // Pressure of one node fixed (needed when no pressure face fixes the constant).
  int pinned_pressure_node = -1;
  double pinned_pressure = 0.0;        // Pa
  std::vector<UrethraOutlet> outlets;  // at most one
};

// The moving (ALE) configuration of one time step: node positions at t_{n+1} (m) and
// the mesh velocity (m/s), e.g. (x_{n+1} − x_n)/Δt from HarmonicMeshMotion.
struct AleFrame {
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Vector3d> mesh_velocity;
  // Per node (empty = none): the mesh velocity is the node's own velocity unknown (the
  // wall nodes of the coupled problem), which the tangent accounts for (StabilizedTet.h).
  std::vector<bool> mesh_follows;
};

}  // namespace vesica::simulate::fluid
