#pragma once
// Newton-Raphson for one load/time step of the wall with its cavity (physics.md §3-4).
// Unknowns: free wall displacements u and the cavity pressure p0. The one scalar cavity
// equation c(u, p0) = 0 is either pressure control (c = p0 - P) or volume control
//   c = V(u) - V_base + θ Δt Q_out(p0)
// (V_base = V_n + Δt Q_in - (1-θ) Δt Q_out,n). The bordered system
//   [K  ∂r/∂p0; ∂c/∂u  ∂c/∂p0] [Δu; Δp0] = -[r; c]
// is solved by its Schur complement with one factorization of K (LinearSolver.h; K may
// be indefinite past the limit point): Δu = u_r + Δp0 u_p, u_r = -K⁻¹ r, u_p = -K⁻¹ ∂r/∂p0.
// An iteration whose wall residual already meets its tolerance reuses the last
// factorization instead of a new one (modified Newton for that small correction only).
//
// Globalization: near a stress-free or slack state K is (nearly) singular against
// inextensional modes and the Newton step is far too long. Such a step is recomputed with
// K + η A (an elastic foundation of η Pa/m on each node's reference area A, raised
// tenfold until the step is short enough) — a pseudo-transient continuation: it changes
// the path of the iteration, never the equations solved, and η decays tenfold per
// accepted iteration so that the final iterations are plain Newton steps again.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "MembraneProblem.h"
#include "vesica/simulate/NewtonOptions.h"

namespace vesica::simulate {

struct CavityEquation {
  bool volume_control = false;
  double pressure_pa = 0.0;     // pressure control: the prescribed p0
  double volume_base_m3 = 0.0;  // volume control: V_base
  // θ Δt Q_out(p0) (m³) and its derivative (m³/Pa); empty = no outflow.
  std::function<double(double p0, double& derivative)> outflow;
};

struct NewtonReport {
  bool converged = false;
  int iterations = 0;
  int regularized_iterations = 0;      // iterations that needed the foundation η > 0
  std::vector<double> residual_norms;  // relative, one per iteration (quadratic convergence)
  std::string failure;                 // why it did not converge
};

class NewtonSolver {
 public:
  explicit NewtonSolver(MembraneProblem& problem, NewtonOptions options = {});

  // Solves for x and loads.inside.p0 starting from their current values. On failure the
  // caller restores its saved state (x, p0) and cuts the step back.
  NewtonReport solve(const CavityEquation& cavity, WallLoads& loads,
                     std::vector<Eigen::Vector3d>& x);

  // The state of the last converged solve (volume, reactions at the fixed dofs).
  const WallAssembly& assembly() const { return assembly_; }

 private:
  // One bordered step with K + η A; refactorizes unless `reuse` and η is unchanged.
  bool bordered_step(const CavityEquation& cavity, double c, double dc_dp, double eta, bool reuse,
                     Eigen::VectorXd& du, double& dp, std::string& failure);

  // Applies α du, α dp with α = 1, 1/2, … 1/16, the first that lowers the merit of the
  // wall and cavity residuals (else 1/16); returns whether assembly_ now holds x's assembly.
  bool line_search(const CavityEquation& cavity, WallLoads& loads, const Eigen::VectorXd& du,
                   double dp, std::vector<Eigen::Vector3d>& x);

  MembraneProblem& problem_;
  NewtonOptions options_;
  WallAssembly assembly_;
  struct Factorization;
  std::shared_ptr<Factorization> lu_;
  double size_ = 1.0;
  double mean_edge_ = 1.0;
  // Reference area per free dof (m²): the elastic foundation η A adds to K's diagonal.
  Eigen::VectorXd foundation_area_;
  double eta_ = 0.0;               // foundation stiffness (Pa/m) carried over between iterations
  double eta_in_K_ = 0.0;          // the part of it added to assembly_.K
  double line_search_step_ = 1.0;  // α of the last line search
};

}  // namespace vesica::simulate
