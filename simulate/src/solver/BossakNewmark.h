#pragma once
// Bossak–Newmark time integration of the wall's inertia (docs/physics.md §3):
//   M [(1 - α_B) a_n+1 + α_B a_n] + f_int(x_n+1) - f_ext = 0,
//   x_n+1 = x_n + Δt v_n + Δt² [(1/2 - β_N) a_n + β_N a_n+1],
//   v_n+1 = v_n + Δt [(1 - γ) a_n + γ a_n+1],
// with α_B ∈ [-1/3, 0], γ = 1/2 - α_B, β_N = (1 - α_B)²/4 (α_B = 0: the trapezoidal rule,
// no numerical damping). M is the lumped wall mass ρ_w H A0 / 3 per node. Solving for
// a_n+1 turns the inertia into a spring of stiffness c M towards a target position:
//   M [(1 - α_B) a_n+1 + α_B a_n] = c M (x_n+1 - x̂),  c = (1 - α_B) / (β_N Δt²),
//   x̂ = x_n + Δt v_n + Δt² (1/2 - β_N) a_n - α_B a_n / c,
// which is how MembraneProblem adds it (WallLoads::inertia).
#include <cstddef>
#include <vector>

#include <Eigen/Dense>

namespace vesica::simulate {

// The inertial "spring" of one step: zero coefficient = quasi-static (no inertia).
struct InertiaTerm {
  double coefficient = 0.0;             // c (1/s²)
  std::vector<Eigen::Vector3d> target;  // x̂ per node (m)
};

class BossakNewmark {
 public:
  // Starts at rest (v = a = 0) for `nodes` nodes. Throws std::invalid_argument for α_B
  // outside [-1/3, 0].
  BossakNewmark(std::size_t nodes, double alpha_b = -0.1);

  double alpha_b() const { return alpha_b_; }
  double gamma() const { return 0.5 - alpha_b_; }
  double beta() const { return 0.25 * (1.0 - alpha_b_) * (1.0 - alpha_b_); }

  // The inertia term of a step of dt (s) from the committed positions x_n (m).
  InertiaTerm inertia(const std::vector<Eigen::Vector3d>& x_n, double dt) const;
  // Accepts the converged positions x_n+1 of that step: updates a and v.
  void commit(const std::vector<Eigen::Vector3d>& x_n, const std::vector<Eigen::Vector3d>& x_new,
              double dt);

  const std::vector<Eigen::Vector3d>& velocity() const { return v_; }      // m/s
  const std::vector<Eigen::Vector3d>& acceleration() const { return a_; }  // m/s²
  // Continues from a saved state (checkpoints); throws std::invalid_argument for another
  // node count.
  void restore(const std::vector<Eigen::Vector3d>& v, const std::vector<Eigen::Vector3d>& a);

 private:
  double alpha_b_;
  std::vector<Eigen::Vector3d> v_, a_;
};

}  // namespace vesica::simulate
