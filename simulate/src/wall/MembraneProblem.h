#pragma once
// The assembled wall: membrane elements, follower pressure of the urine inside and the
// abdomen outside, wall weight and elastic supports, with fixed degrees of freedom
// removed. Assembles the residual r = f_int - f_ext over the free degrees of freedom,
// its tangent K = ∂r/∂u (sparse, pattern built once and reused), ∂r/∂p0 and the volume
// gradient ∂V/∂u for the bordered cavity system (docs/physics.md §4).
#include <array>
#include <memory>
#include <vector>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "solver/BossakNewmark.h"
#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/wall/WallModel.h"
#include "wall/MembraneElement.h"
#include "wall/PressureLoad.h"

namespace vesica::simulate {

struct WallLoads {
  HydrostaticPressure inside;   // urine; inside.p0 is the cavity pressure unknown
  HydrostaticPressure outside;  // abdominal pressure on the outer face (Pa); outside.p0 = Pabd
  Eigen::Vector3d wall_gravity = Eigen::Vector3d::Zero();  // m/s² acting on the wall mass
  double wall_density = 920.0;                             // kg/m³ (docs/physics.md §2)
  double support_stiffness = 0.0;  // springs of the support region, Pa/m (per unit area)
  double activation = 0.0;         // detrusor activation a(t) ∈ [0, 1]
  double dt_s = 0.0;               // time step (viscoelastic history)
  // Wall inertia of a dynamic step (BossakNewmark.h); empty coefficient = quasi-static.
  InertiaTerm inertia;
  // Viscous drag of the surrounding tissue, c (x - x_n) / Δt per unit reference area:
  // a spring of stiffness c/Δt (Pa/m) towards the last converged positions x_n. It is
  // what makes a slack or wrinkled wall (no stiffness against bending-like modes) a
  // well-posed problem at every step; 0 = none.
  double drag_stiffness = 0.0;               // c / Δt (Pa/m)
  std::vector<Eigen::Vector3d> drag_anchor;  // x_n (m)
};

struct WallAssembly {
  Eigen::VectorXd residual;       // free dofs, f_int - f_ext (N)
  Eigen::VectorXd full_residual;  // all 3N dofs; at fixed dofs: minus the reactions
  Eigen::SparseMatrix<double> K;  // ∂residual/∂u, free dofs (N/m)
  Eigen::VectorXd dr_dp0;         // ∂residual/∂p0 = -∂f_ext/∂p0 (m²)
  Eigen::VectorXd dV_du;          // ∂V/∂u, free dofs (m²)
  double volume = 0.0;            // enclosed volume (m³)
  double force_scale = 0.0;       // max(|f_int|, |f_ext|) for relative tolerances (N)
};

class MembraneProblem {
 public:
  // Throws vesica::Error (file "mesh") for a degenerate reference triangle.
  MembraneProblem(const WallModel& wall, const Material& material, int threads = 2);

  const WallModel& wall() const { return wall_; }
  std::size_t free_dof_count() const { return free_count_; }
  // Global dof (3 node + i) → free index or -1.
  const std::vector<int>& dof_map() const { return dof_; }
  // Reference tributary area per node, a third of each adjacent triangle's (m²).
  const std::vector<double>& node_areas() const { return node_area_; }

  // Evaluates every element at x with the committed history; tangent only when asked.
  // Throws std::runtime_error when an element fails (inverted, thickness iteration).
  void assemble(const std::vector<Eigen::Vector3d>& x, const WallLoads& loads, bool with_tangent,
                WallAssembly& out);
  // Wrinkling membrane (TensionField.h): no compressive stress anywhere. Off by default
  // so that the element-level verification sees the plain plane-stress law.
  void set_tension_field(bool on) { tension_field_ = on; }
  bool tension_field() const { return tension_field_; }
  // The share ε of the plain law a wrinkled or slack element keeps (TensionField.h).
  void set_wrinkle_regularisation(double epsilon) { wrinkle_regularisation_ = epsilon; }

  // How many elements the last assemble() found taut, wrinkled and slack (TensionField.h):
  // the step log of a cystometry (docs/simulate.md, "Step log").
  std::array<int, 3> wrinkling_counts() const;

  // Accepts the state of the last assemble() as converged (history, thickness guesses).
  void commit();
  // Takes over the committed state (history, thickness guesses) of another problem on the
  // same wall and material: a model that continues where another one stopped.
  void copy_committed_state(const MembraneProblem& other);
  // The committed state as numbers, for checkpoints: the material history of every element,
  // then its squared volume ratio. restore_committed_state throws std::invalid_argument
  // for another wall's or material's state.
  const std::vector<double>& committed_history() const { return history_old_; }
  const std::vector<double>& committed_volume_ratios() const { return J2_old_; }
  void restore_committed_state(const std::vector<double>& history, const std::vector<double>& J2);

  // x += du on the free dofs.
  void apply_increment(const Eigen::VectorXd& du, std::vector<Eigen::Vector3d>& x) const;

  // Cauchy stresses, thickness and stretches per element at x (committed history).
  std::vector<MembraneStressOutput> element_outputs(const std::vector<Eigen::Vector3d>& x,
                                                    const WallLoads& loads) const;

 private:
  void build_pattern();
  template <class Body>
  void for_each_element(const Body& body) const;
  // Calls spring(k, anchor) for every node spring acting on node n (support, inertia,
  // tissue drag): the force k (x - anchor) with k in N/m.
  template <class Spring>
  void for_each_node_spring(std::size_t n, const WallLoads& loads, const Spring& spring) const;

  const WallModel& wall_;
  const Material& material_;
  int threads_;
  bool tension_field_ = false;
  double wrinkle_regularisation_ = 0.0;
  std::vector<MembraneGeometry> geometry_;
  std::vector<MaterialPoint> points_;
  std::vector<int> dof_;
  std::size_t free_count_ = 0;
  std::size_t history_size_ = 0;
  std::vector<double> history_old_, history_new_;
  // Squared volume ratio per element: committed, and of the last evaluation (the guess of
  // the next plane-stress iteration, PlaneStress.h).
  std::vector<double> J2_old_, J2_new_;
  std::vector<Wrinkling> wrinkling_;  // per element, of the last evaluation
  std::vector<double> node_area_;     // reference tributary area per node (m²)
  std::vector<double> node_mass_;     // wall mass per node (kg / (kg/m³)): H A0 / 3 sums
  // Per element: its 9x9 block (membrane - pressure) and where each entry goes in K.
  std::vector<Matrix9> element_K_;
  std::vector<Vector9> element_f_;
  std::vector<Vector9> element_fp_, element_dfdp0_, element_dV_;
  std::vector<double> element_V_;
  std::vector<std::array<int, 81>> slot_;
  std::vector<int> diagonal_slot_;  // per free dof
  Eigen::SparseMatrix<double> pattern_;
};

}  // namespace vesica::simulate
