#pragma once
// The one Newton loop of simulate (docs/physics.md §3), with its safeguards
// (NewtonOptions.h): the elastic foundation for steps that would move the wall too far,
// the line search for a wrinkling wall, tangent reuse, the iteration budget and the
// divergence test. What differs between the nonlinear systems (the wall with its cavity in
// NewtonSolver, the coupled wall and urine in FluidWallCoupling, the urine alone in
// FluidNewton) is behind NewtonSystem: how they evaluate, solve, measure and apply an
// increment and what they call converged.
//
// One iteration: test convergence (the increment just applied, then the residual at the
// iterate if the system tests it); solve for an increment, on a foundation η A raised while
// the increment moves a wall node too far; apply it, shortened by the line search where the
// system has a merit function.
#include <string>
#include <vector>

#include <Eigen/Sparse>

#include "vesica/simulate/solver/NewtonOptions.h"
#include "wall/ElasticFoundation.h"

namespace vesica::simulate {

struct NewtonReport {
  bool converged = false;
  // Increments computed; a failed iteration (its evaluation or solve threw) counts.
  int iterations = 0;
  int regularized_iterations = 0;      // iterations that needed the foundation η > 0
  std::vector<double> residual_norms;  // relative, one per iteration, where the system has one
  std::string failure;                 // why it did not converge
};

// The residual's verdict at an iterate (systems that test the residual).
struct ResidualCheck {
  bool converged = false;  // every residual meets its tolerance
  // The wall is in equilibrium already: only a small correction is left (the cavity
  // equation, or the increment test), which the last factorization serves as well.
  bool equilibrium = false;
  double norm = 0.0;    // relative residual, for the divergence test and tangent reuse
  std::string failure;  // e.g. a non-finite residual: the solve fails at once
};

// A nonlinear system R(z) = 0 for the loop. Its unknowns z start with the free wall dofs in
// MembraneProblem's order (the foundation acts on those); the rest are its own.
class NewtonSystem {
 public:
  virtual ~NewtonSystem() = default;

  virtual std::size_t unknown_count() const = 0;
  // The part of convergence known before the residual: after `increments` increments, the
  // last of which moved a wall node by at most `move` (m; INFINITY before the first).
  virtual bool increment_converged(int increments, double move) const = 0;
  // Whether convergence needs the residual at the iterate too (then it is evaluated first).
  virtual bool tests_residual() const = 0;
  // Evaluates residual and tangent at the current iterate. Throws std::runtime_error when
  // the iterate is not admissible (an inverted element, a failed local iteration).
  virtual void evaluate() = 0;
  // After evaluate(), systems that test the residual: its verdict.
  virtual ResidualCheck check_residual() { return {}; }
  // The tangent of the last evaluate(); the foundation adds η A to its wall diagonal.
  virtual Eigen::SparseMatrix<double>& tangent() = 0;
  // The increment: tangent⁻¹ (−residual); reuse: solve with the last factorization instead
  // of factorizing tangent(). Returns false with the reason, or throws std::runtime_error.
  virtual bool solve_increment(bool reuse, std::string& failure) = 0;
  // After solve_increment: whether its factorization may serve later increments (false
  // where it is already known to be far from the tangent).
  virtual bool factorization_reusable() const { return true; }
  // The longest move of a wall node in the increment (m); 0 without a wall.
  virtual double increment_move() const = 0;
  // The move this iteration's equations demand of the wall (m), e.g. a cavity's volume
  // change: added to the foundation's limit, since it is no sign of a slack mode.
  virtual double demanded_move() const { return 0.0; }
  // Adds the increment to the iterate.
  virtual void apply_increment() = 0;

  // Line search, for systems with a merit function (where line_search_applies()):
  virtual bool line_search_applies() const { return false; }
  // Keeps the iterate as the line search's start; returns its merit.
  virtual double begin_line_search() { return 0.0; }
  // Moves to start + fraction × increment and evaluates there; false when that iterate
  // is not admissible. merit: its merit.
  virtual bool try_fraction(double /*fraction*/, double& /*merit*/) { return false; }
  // Keeps the last tried iterate and its evaluation as the next iteration's.
  virtual void keep_trial() {}
};

class NewtonLoop {
 public:
  explicit NewtonLoop(const NewtonOptions& options, ElasticFoundation foundation = {});

  // Iterates from the system's current state. On failure the system is left at the last
  // iterate: the caller restores its saved state (and cuts the step back).
  NewtonReport solve(NewtonSystem& system);
  // Forgets what the loop carries from one solve to the next (the foundation's η, whether
  // the system's last factorization may be reused), as for a new system or a new time step.
  void reset();
  // What the loop carries from one solve to the next (checkpoints).
  struct Carried {
    double eta = 0.0;
    bool tangent_reusable = false;
  };
  Carried carried() const { return {eta_, tangent_reusable_}; }
  void restore(const Carried& c) { eta_ = c.eta, tangent_reusable_ = c.tangent_reusable; }

  const NewtonOptions& options() const { return options_; }

 private:
  int budget(const NewtonReport& report) const;
  bool diverging(const NewtonReport& report, int iteration) const;
  bool stagnating(const NewtonReport& report, int iteration) const;
  // Solves for the increment on the foundation; returns its longest wall move.
  double regularized_increment(NewtonSystem& system, bool reuse, bool& reusable,
                               NewtonReport& report);
  // Applies the increment, halved while the merit does not fall; returns the fraction taken
  // and whether the system now holds the evaluation of the new iterate.
  double line_search(NewtonSystem& system, bool& evaluated) const;

  NewtonOptions options_;
  ElasticFoundation foundation_;
  double eta_ = 0.0;  // foundation stiffness (Pa/m) carried to the next iteration
  // The system's factorization belongs to a converged state or to this solve (reuse rule).
  bool tangent_reusable_ = false;
};

}  // namespace vesica::simulate
