#pragma once
// One P1-P1 tetrahedron of incompressible Navier–Stokes, stabilized by SUPG, PSPG and
// LSIC, backward Euler in time (docs/navier-stokes.md §2). With r_M = ρ(∂u/∂t + (c·∇)u)
// + ∇p − ρg (the viscous term vanishes in a P1 element) the element residual is
//   momentum:   ∫ N_a ρ(∂u/∂t + (c·∇)u) + 2μ ε(u)∇N_a − p ∇N_a − N_a ρ g
//               + τ_M ρ (c·∇N_a) r_M + τ_C (∇·u) ∇N_a
//   continuity: ∫ N_a ∇·u + τ_M ∇N_a·r_M
// with τ_M = [(2ρ/Δt)² + (2ρ|c|/h)² + (24μ/h²)²]^(-1/2), τ_C = h²/(6 τ_M),
// h = 2(3V/4π)^(1/3) (docs/navier-stokes.md §2 says why 24), c = u − w_mesh the convective velocity
// (ALE). The tangent is the exact derivative of this residual (τ included), for quadratic Newton
// convergence.
#include <array>

#include <Eigen/Dense>

#include "fluid/FluidModel.h"

namespace vesica::simulate::fluid {

using TetVector = Eigen::Matrix<double, 16, 1>;
using TetMatrix = Eigen::Matrix<double, 16, 16>;

struct TetState {
  std::array<Eigen::Vector3d, 4> x;      // node positions, m
  std::array<Eigen::Vector3d, 4> u;      // velocity now, m/s
  std::array<double, 4> p{};             // pressure now, Pa
  std::array<Eigen::Vector3d, 4> u_old;  // velocity at the previous time, m/s
  std::array<Eigen::Vector3d, 4> w_mesh{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                        Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  // Node a's mesh velocity is its velocity (a wall node of the coupled problem: both are
  // the wall's (x − x_n)/Δt): its tangent column is then d/du_a with w_a = u_a, in which
  // the convective velocity c = u − w does not change.
  std::array<bool, 4> mesh_follows{false, false, false, false};
};

// Shape-function gradients (rows, 1/m) and volume (m³) of a tetrahedron; throws
// std::runtime_error for a degenerate one.
void tet_gradients(const std::array<Eigen::Vector3d, 4>& x, Eigen::Matrix<double, 4, 3>& grad,
                   double& volume);

// inverse_dt = 1/Δt (1/s), 0 for a steady solve. Residual (N, m³/s) and its tangent;
// dof order (u_x, u_y, u_z, p) per node.
void stabilized_tet(const TetState& state, const FluidProperties& fluid, double inverse_dt,
                    TetVector& residual, TetMatrix* tangent);

}  // namespace vesica::simulate::fluid
