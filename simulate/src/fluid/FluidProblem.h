#pragma once
// Assembly of the stabilized P1-P1 Navier–Stokes system on a fixed tetrahedral mesh
// (docs/navier-stokes.md §2): residual R(U) and Jacobian ∂R/∂U with velocity conditions
// and the pinned pressure imposed by row replacement, and pressure faces as the traction
// −p̄ n. State U as in FluidMesh.h (m/s, Pa); residual rows in N (momentum) and m³/s
// (continuity), Pa (outlet law).
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "fluid/BoundaryFaces.h"
#include "fluid/FluidBoundary.h"
#include "fluid/FluidModel.h"

namespace vesica::simulate::fluid {

class FluidProblem {
 public:
  // Throws std::invalid_argument for a condition on a node outside the mesh or a pressure
  // face that is not a boundary triangle.
  FluidProblem(const FluidMesh& mesh, const FluidBoundary& boundary, const FluidProperties& fluid);

  int node_dof_count() const { return kDofsPerNode * static_cast<int>(mesh_.nodes.size()); }
  // Node dofs, plus the outlet pressure when there is an outlet.
  int dof_count() const { return node_dof_count() + (has_outlet() ? 1 : 0); }
  bool has_outlet() const { return !boundary_.outlets.empty(); }
  const FluidMesh& mesh() const { return mesh_; }
  const BoundaryFaces& boundary_faces() const { return faces_; }
  const FluidProperties& fluid() const { return fluid_; }

  // A state at rest satisfying the velocity conditions, with the hydrostatic pressure
  // through the outlet (at its opening pressure) or the pinned node.
  Eigen::VectorXd initial_state() const;
  // Sets the constrained dofs of state to their values (the Jacobian assumes they hold).
  void apply_constraints(Eigen::VectorXd& state) const;

  // inverse_dt = 1/Δt (1/s), 0 for steady flow; state_old is the previous time's state
  // at the same nodes. frame: the moved mesh and its velocity (ALE); null = the fixed mesh.
  void assemble(const Eigen::VectorXd& state, const Eigen::VectorXd& state_old, double inverse_dt,
                Eigen::VectorXd& residual, Eigen::SparseMatrix<double>* jacobian,
                const AleFrame* frame = nullptr) const;

 private:
  // The element part of assemble() over tets [begin, end): its residual, triplets and
  // largest free diagonal entry.
  struct ElementShare {
    Eigen::VectorXd residual;
    std::vector<Eigen::Triplet<double>> triplets;
    double diagonal_scale = 0.0;
  };
  void assemble_elements(std::size_t begin, std::size_t end, const std::vector<Eigen::Vector3d>& x,
                         const Eigen::VectorXd& state, const Eigen::VectorXd& state_old,
                         double inverse_dt, bool with_jacobian, const AleFrame* frame,
                         ElementShare& out) const;
  void add_outlet(const Eigen::VectorXd& state, const std::vector<Eigen::Vector3d>& x,
                  Eigen::VectorXd& residual, std::vector<Eigen::Triplet<double>>* triplets) const;

  const FluidMesh& mesh_;
  FluidBoundary boundary_;
  FluidProperties fluid_;
  BoundaryFaces faces_;
  std::vector<bool> constrained_;      // per dof
  Eigen::VectorXd constrained_value_;  // per dof
};

}  // namespace vesica::simulate::fluid
