#pragma once
// Level-2 wall–urine coupling, solved monolithically (docs/navier-stokes.md §3): one
// Newton system for the free wall positions, the urine velocity and pressure at the
// interior tet nodes and the pressure at the wall nodes. The urine velocity at a wall node
// is not an unknown: it is the wall velocity (x − x_n)/Δt (backward Euler, the same rule
// as the wall's inertia here, so both sides of the interface move alike). The urine's
// momentum rows of a wall node are added to the wall residual there (the traction of the
// urine on the wall), and the interior of the tet mesh follows the wall by the harmonic
// mesh motion. One UMFPACK solve per iteration for all unknowns, so no added-mass
// instability whatever the densities.
//
// Jacobian: exact for the membrane (K, inertia) and for the urine at fixed geometry
// (∂R/∂(u, p), with ∂u_wall/∂x = I/Δt). Its dependence on the geometry is approximated by
// the follower-pressure stiffness of the wall triangles at their mean nodal pressure; the
// motion of the interior nodes is lagged (quasi-Newton: more iterations, same solution).
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "vesica/simulate/MembraneProblem.h"
#include "vesica/simulate/fluid/FluidMesh.h"
#include "vesica/simulate/fluid/FluidModel.h"

namespace vesica::simulate::fluid {

// A ureter inlet reduced to one wall node held fixed (all three wall dofs): the urine
// enters there along the inward normal at the prescribed rate (m³/s), scaled on the
// current geometry so that the discrete P1 flux through its faces is exactly the rate.
struct InletNode {
  int node = -1;
  double flow_rate = 0.0;
};

struct CouplingOptions {
  int max_iterations = 40;
  double position_tolerance = 1e-9;  // max |Δx| relative to the wall's size
  double pressure_tolerance = 1e-7;  // max |Δp| relative to max(|p|, 1 Pa)
};

struct CouplingReport {
  bool converged = false;
  int iterations = 0;
  std::string failure;
};

class FluidWallCoupling {
 public:
  // mesh: tetrahedra whose nodes 0..N−1 are the wall's nodes (N = wall node count, same
  // reference positions), as vesica-mesh builds them. Keeps references to wall and mesh.
  // Throws std::invalid_argument when the mesh does not start with the wall nodes.
  FluidWallCoupling(MembraneProblem& wall, const FluidMesh& mesh, const FluidProperties& fluid,
                    CouplingOptions options = {});
  ~FluidWallCoupling();

  // One backward-Euler step of dt (s). loads: the wall's loads without the urine
  // (loads.inside must be zero: the urine's traction replaces it); its inertia is set
  // here. On convergence the step is committed (wall history, positions, velocities).
  CouplingReport step(double dt, const WallLoads& loads, const InletNode& inlet);

  const std::vector<Eigen::Vector3d>& positions() const { return x_; }  // all tet nodes, m
  const Eigen::VectorXd& state() const { return state_; }  // as in FluidMesh.h, m/s and Pa
  const std::vector<Eigen::Vector3d>& wall_velocity() const { return wall_velocity_; }
  // Volume of the tetrahedra at the current positions (m³).
  double fluid_volume() const;
  // ½ ∫ ρ |u|² with the P1 mass lumped (V_e/4 per corner), J.
  double fluid_kinetic_energy() const;

 private:
  struct Unknowns;
  void build_unknowns();
  void set_wall_velocities(const std::vector<Eigen::Vector3d>& x_wall, double dt,
                           const InletNode& inlet);
  void move_mesh(const std::vector<Eigen::Vector3d>& x_wall);
  WallLoads step_loads(double dt, const WallLoads& loads_in, const InletNode& inlet) const;
  // Assembles the coupled residual and Jacobian at the current state and solves; throws
  // std::runtime_error when an element, the mesh or the factorization fails.
  Eigen::VectorXd newton_increment(double dt, const WallLoads& loads,
                                   const std::vector<Eigen::Vector3d>& x_wall,
                                   const Eigen::SparseMatrix<double>& columns,
                                   const Eigen::SparseMatrix<double>& rows);
  double apply_urine_increment(const Eigen::VectorXd& dz);  // returns max |Δp|
  void commit(double dt, const WallLoads& loads, const std::vector<Eigen::Vector3d>& x_wall,
              const InletNode& inlet);

  MembraneProblem& wall_;
  const FluidMesh& mesh_;
  FluidProperties fluid_;
  CouplingOptions options_;
  std::unique_ptr<Unknowns> unknowns_;
  std::vector<Eigen::Vector3d> x_, x_old_;  // tet node positions now and at t_n
  std::vector<Eigen::Vector3d> wall_velocity_;
  Eigen::VectorXd state_, state_old_;
};

}  // namespace vesica::simulate::fluid
