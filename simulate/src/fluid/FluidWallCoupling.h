#pragma once
// Level-2 wall–urine coupling, solved monolithically (docs/navier-stokes.md §3): one
// Newton system for the free wall positions, the urine velocity and pressure at the
// interior tet nodes and the pressure at the wall nodes. The urine velocity at a wall node
// is not an unknown: it is the wall velocity (x − x_n)/Δt (backward Euler, the same rule
// as the wall's inertia here, so both sides of the interface move alike). The urine's
// momentum rows of a wall node are added to the wall residual there (the traction of the
// urine on the wall), and the interior of the tet mesh follows the wall by the harmonic
// mesh motion. One sparse LU per iteration for all unknowns (LinearSolver), so no
// added-mass instability whatever the densities. The iteration is the one Newton loop
// (NewtonLoop.h) with the elastic foundation on the wall dofs (coupled_newton_options()),
// converged when the last increment moved no wall node by more than increment_tolerance
// of the wall's size and changed no pressure by more than pressure_tolerance.
//
// Jacobian: exact for the membrane (K, inertia) and for the urine at fixed geometry
// (∂R/∂(u, p), with ∂u_wall/∂x = I/Δt). Its dependence on the geometry is approximated by
// the follower-pressure stiffness of the wall triangles at their mean nodal pressure; the
// motion of the interior nodes is lagged (quasi-Newton: more iterations, same solution).
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "fluid/CoupledLinearSolver.h"
#include "fluid/FluidBoundary.h"
#include "fluid/FluidModel.h"
#include "fluid/MeshMotion.h"
#include "solver/NewtonLoop.h"
#include "wall/MembraneProblem.h"
#include "wall/PressureLoad.h"

namespace vesica::simulate {
class CheckpointWriter;
class CheckpointReader;
}  // namespace vesica::simulate

namespace vesica::simulate::fluid {

// Inflow at a prescribed rate (m³/s) through a patch of wall triangles whose nodes the
// wall holds fixed (a ureter orifice, or the urethral catheter of a cystometry): a plug
// along the inward normals at the patch's inner nodes (those in no triangle outside the
// patch), zero on its rim, scaled on the current geometry so that the discrete P1 flux is
// exactly the rate.
struct Inflow {
  std::vector<std::array<int, 3>> faces;
  double flow_rate = 0.0;
};

// The failure of a step whose converged state inverted a urine tetrahedron.
inline constexpr const char* kInvertedTet = "a urine tetrahedron inverted";

// The fan of wall triangles around one node: an inlet reduced to a single node.
Inflow inflow_at_node(const WallModel& wall, int node, double flow_rate);

class FluidWallCoupling {
 public:
  // mesh: tetrahedra whose nodes 0..N−1 are the wall's nodes (N = wall node count, same
  // reference positions), as vesica-mesh builds them. Keeps a reference to wall and a copy
  // of mesh (remesh() replaces it).
  // Throws std::invalid_argument when the mesh does not start with the wall nodes.
  FluidWallCoupling(MembraneProblem& wall, const FluidMesh& mesh, const FluidProperties& fluid,
                    const NewtonOptions& options = coupled_newton_options(),
                    Level2LinearSolver linear_solver = Level2LinearSolver::Krylov);
  ~FluidWallCoupling();

  // One backward-Euler step of dt (s). loads: the wall's loads without the urine
  // (loads.inside must be zero: the urine's traction replaces it); its inertia is set
  // here. On convergence the step is committed (wall history, positions, velocities);
  // otherwise the state stays at the last committed step. Throws std::invalid_argument
  // when an inflow node is not held fixed by the wall.
  NewtonReport step(double dt, const WallLoads& loads, const Inflow& inflow);

  // Urine at rest with the hydrostatic pressure p = p_ref + ρ g·(x − x_ref) (Pa, m): the
  // equilibrium start when the wall's outside load balances it.
  void set_hydrostatic_state(double p_ref, const Eigen::Vector3d& x_ref);
  // Starts from a deformed wall at rest (e.g. level 1's equilibrium at the start volume):
  // wall node positions (m), the interior following by the mesh motion. Call before
  // set_hydrostatic_state.
  void set_wall_positions(const std::vector<Eigen::Vector3d>& x_wall);
  // Opens the urethra: the outlet faces (wall triangles held fixed) carry the traction of
  // the urethra law (FluidMesh.h) and their inner nodes get free urine velocities. The
  // outlet pressure starts at the hydrostatic value at the patch centroid.
  void open_outlet(const UrethraOutlet& outlet);
  bool outlet_open() const { return outlet_.has_value(); }
  // Outflow through the open outlet (m³/s, positive out), 0 when closed.
  double outflow() const;
  // Pressure of the open outlet's law (Pa) at its centroid.
  double outlet_pressure() const;

  const std::vector<Eigen::Vector3d>& positions() const { return x_; }  // all tet nodes, m
  // The unknowns as in FluidMesh.h (m/s and Pa; with the outlet open, p_out last), with
  // the modified pressure p̃ = p − ρ g·(x − x_h) (no hydrostatic part; = p without gravity).
  const Eigen::VectorXd& state() const { return state_; }
  // The same with the full pressure p.
  Eigen::VectorXd full_state() const;
  // The tetrahedra at the current positions.
  FluidMesh current_mesh() const;
  const std::vector<Eigen::Vector3d>& wall_velocity() const { return wall_velocity_; }
  // The tetrahedra at the positions where they were built (the reference mesh, or the
  // wall at the last remesh()): the reference of the mesh motion and of the orientation.
  const FluidMesh& mesh() const { return mesh_; }
  // Rebuilds the tetrahedra from the wall at its current positions with gmsh (the wall
  // nodes stay nodes 0..N−1), when the moving ones have degraded (docs/navier-stokes.md
  // §1). The urine velocity moves to the new nodes by P1 interpolation in the old
  // tetrahedra and is then projected onto the new mesh's divergence-free velocities
  // (DivergenceFreeProjection.h), the pressure by interpolation; the wall, its velocities
  // and the outlet stay. Call between steps (the state at t_n is the state now).
  // max_size_mm: longest new tet edge (0 = the current wall's mean edge). Returns the new
  // tetrahedron count; throws vesica::Error when gmsh fails (the old mesh then stays).
  int remesh(double max_size_mm = 0.0);
  // The same with about target_tets tetrahedra (within the relative tolerance; the closest
  // count gmsh gave in a few runs otherwise), the resolution of the mesh it replaces.
  int remesh_matched(std::size_t target_tets, double tolerance);
  // Sets the urine state, now and at t_n (size and units as state()), e.g. an initial flow.
  void set_state(const Eigen::VectorXd& state);
  // Volume of the tetrahedra at the current positions (m³).
  double fluid_volume() const;
  // ½ ∫ ρ |u|² with the P1 mass lumped (V_e/4 per corner), J.
  double fluid_kinetic_energy() const;
  // What the linear solves cost so far (CoupledLinearSolver.h).
  // Checkpoints (NavierStokesCavityState.cpp): the committed state between two steps
  // with the urethra closed (tetrahedra, positions, velocities, urine state, the last
  // remesh's size, the linear solver's kept factors); restore_state on a coupling of the
  // same wall, fluid and options. Throws std::logic_error when the outlet is open.
  void save_state(CheckpointWriter& out) const;
  void restore_state(CheckpointReader& in);

  nlohmann::json linear_solver_statistics() const {
    nlohmann::json s = solver_.json();
    s["assemble_s"] = assemble_s_;
    return s;
  }

 private:
  struct Unknowns;
  class System;  // one step's coupled equations for the Newton loop
  void build_unknowns();
  FluidBoundary outlet_boundary() const;  // the open outlet's law in the modified pressure
  void set_wall_velocities(const std::vector<Eigen::Vector3d>& x_wall, double dt,
                           const Inflow& inflow);
  void move_mesh(const std::vector<Eigen::Vector3d>& x_wall);        // interior by mesh motion
  void move_wall_nodes(const std::vector<Eigen::Vector3d>& x_wall);  // interior stays
  WallLoads step_loads(double dt, const WallLoads& loads_in, const Inflow& inflow) const;
  double apply_urine_increment(const Eigen::VectorXd& dz);  // returns max |Δp|
  void replace_tetrahedra(FluidMesh fresh);                 // transfer and projection of the state
  void adopt_tetrahedra(FluidMesh mesh);  // a restarted run's: its mesh motion and unknowns
  std::vector<bool> given_velocities() const;
  void commit(double dt, const WallLoads& loads, const std::vector<Eigen::Vector3d>& x_wall,
              const Inflow& inflow);

  MembraneProblem& wall_;
  FluidMesh mesh_;
  FluidProperties fluid_;
  NewtonLoop loop_;
  CoupledLinearSolver solver_;
  std::unique_ptr<Unknowns> unknowns_;
  HydrostaticPressure hydrostatic_part() const;  // ρ g·(x − x_h), the wall load it makes

  std::unique_ptr<HarmonicMeshMotion> motion_;
  Eigen::Vector3d x_hydrostatic_;           // x_h: reference height of the hydrostatic part
  std::optional<UrethraOutlet> outlet_;     // empty while the urethra is closed
  std::vector<Eigen::Vector3d> x_, x_old_;  // tet node positions now and at t_n
  std::vector<Eigen::Vector3d> wall_velocity_;
  Eigen::VectorXd state_, state_old_;
  double assemble_s_ = 0.0;  // wall-clock seconds in the coupled assembly
  // The longest edge of the last size-matched remesh (mm) and the volume then (m³).
  double remesh_size_mm_ = 0.0, remesh_volume_ = 1.0;
};

}  // namespace vesica::simulate::fluid
