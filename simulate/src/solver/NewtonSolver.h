#pragma once
// Newton-Raphson for one load/time step of the wall with its cavity (docs/physics.md §3-4),
// as a system of the one Newton loop (NewtonLoop.h), whose foundation and line-search
// safeguards it uses (NewtonOptions.h).
// Unknowns: free wall displacements u and the cavity pressure p0. The one scalar cavity
// equation c(u, p0) = 0 is either pressure control (c = p0 - P) or volume control
//   c = V(u) - V_base + θ Δt Q_out(p0)
// (V_base = V_n + Δt Q_in - (1-θ) Δt Q_out,n). The bordered system
//   [K  ∂r/∂p0; ∂c/∂u  ∂c/∂p0] [Δu; Δp0] = -[r; c]
// is solved by its Schur complement with one factorization of K (LinearSolver.h; K may
// be indefinite past the limit point): Δu = u_r + Δp0 u_p, u_r = -K⁻¹ r, u_p = -K⁻¹ ∂r/∂p0.
// Converged when the wall residual, the cavity equation and the last increment meet their
// tolerances. An iteration whose wall residual already meets its tolerance reuses the last
// factorization instead of a new one (modified Newton for that small correction only).
// On a wrinkling wall the line search's merit is the sum of the squared wall and cavity
// residuals, each relative to its value at the start of the iteration.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "solver/LinearSolver.h"
#include "solver/NewtonLoop.h"
#include "vesica/simulate/solver/NewtonOptions.h"
#include "wall/MembraneProblem.h"

namespace vesica::simulate {

struct CavityEquation {
  bool volume_control = false;
  double pressure_pa = 0.0;     // pressure control: the prescribed p0
  double volume_base_m3 = 0.0;  // volume control: V_base
  // θ Δt Q_out(p0) (m³) and its derivative (m³/Pa); empty = no outflow.
  std::function<double(double p0, double& derivative)> outflow;
};

class LinearSolver;

class NewtonSolver {
 public:
  explicit NewtonSolver(MembraneProblem& problem, NewtonOptions options = {});
  ~NewtonSolver();

  // Solves for x and loads.inside.p0 starting from their current values. On failure the
  // caller restores its saved state (x, p0) and cuts the step back. The foundation's
  // stiffness and the factorization carry over from one solve to the next.
  NewtonReport solve(const CavityEquation& cavity, WallLoads& loads,
                     std::vector<Eigen::Vector3d>& x);

  // The state of the last converged solve (volume, reactions at the fixed dofs).
  const WallAssembly& assembly() const { return assembly_; }

  // What carries over from one solve to the next, for checkpoints (HydrostaticCavityState.cpp):
  // the loop's foundation and tangent reuse, and the last factorization's matrix (kept
  // from keep_factorized_matrix() on).
  void keep_factorized_matrix();
  struct Carried {
    NewtonLoop::Carried loop;
    LinearSolver::Memory lu;
  };
  Carried carried() const;
  void restore(const Carried& carried);

 private:
  class System;
  MembraneProblem& problem_;
  NewtonLoop loop_;
  WallAssembly assembly_;
  std::unique_ptr<LinearSolver> lu_;
  double size_ = 1.0;  // diagonal of the reference wall's bounding box (m)
};

}  // namespace vesica::simulate
