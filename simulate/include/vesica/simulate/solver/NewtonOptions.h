#pragma once
// The settings of the Newton iteration that solves each step of a cystometry (docs/physics.md
// §3): the wall with its cavity (level 1), the coupled wall and urine (level 2) and the urine
// alone run the same loop (simulate/src/solver/NewtonLoop.h) with its safeguards named here. SI.
namespace vesica::simulate {

// The elastic-foundation safeguard: a stress-free or slack membrane has (nearly) no
// stiffness against bending-like modes, so a plain Newton step there moves nodes orders of
// magnitude too far. A step that would move a wall node further than the limit is
// recomputed with K + η A (a foundation of η Pa/m on each node's reference area A), η
// raised until the step is short enough; η decays at every iteration, so the final
// iterations are plain Newton steps again. A pseudo-transient continuation: it changes the
// iteration's path, never the equations solved.
struct FoundationOptions {
  // Longest node move of one iteration, in mean reference edges (0 = no foundation). The
  // move the equations themselves demand (a cavity's volume change) is added to it.
  double max_move_per_edge = 0.5;
  // η of the first raise, as a fraction of the tangent's diagonal stiffness per reference
  // area (the wall's own stiffness scale, Pa/m): small enough to leave a well-posed step
  // nearly untouched.
  double first_stiffness = 1e-6;
  double raise_factor = 10.0;  // η ← raise_factor η while the step is still too long
  int max_raises = 12;         // after this many raises the step is taken as it is
  double decay_factor = 0.1;   // η of the next iteration ← decay_factor η
  // η below this fraction of the stiffness scale drops to zero instead of decaying on.
  double off_below = 1e-9;
};

// The line-search safeguard of a wrinkling wall: its elements switch between slack (no
// stiffness) and taut (full stiffness), and the full Newton step can jump across such a
// switch and back forever (a 2-cycle of the residual). The step is halved until the merit
// (the system's residuals, each relative to its value at the start of the iteration) falls.
struct LineSearchOptions {
  // Used by systems that have a merit function and need it (the wall with its cavity, when
  // the wall wrinkles); never on the first iteration of a solve.
  bool enabled = true;
  int max_halvings = 4;  // the shortest step is 2⁻⁴ of Newton's, taken even if the merit rose
};

// Preconditioned reuse of a factorization (inexact Newton; the wall with its cavity): an
// iteration that may reuse the last factorization of the tangent solves with the current
// tangent by GMRES preconditioned by that factorization (solver/PreconditionedGmres.h)
// instead of a new one, across iterations and steps. The increment is Newton's to the
// linear tolerance, so the iteration converges as with fresh factorizations. Where the
// tangent has moved too far (a wrinkling wall's elements switching between slack and taut,
// the limit point) GMRES does not reach the tolerance within max_iterations and the
// tangent is factorized afresh; one that needed more than refactorize_after solves is
// factorized afresh at the next iteration, before the reuse gets expensive.
struct PreconditionedReuseOptions {
  int max_iterations = 0;  // preconditioner solves per right-hand side (0: off, chord reuse)
  int refactorize_after = 4;
  double tolerance = 1e-10;  // |K Δu + r| / |r| of each linear solve
};

struct NewtonOptions {
  int max_iterations = 15;
  // Iterations whose step needed the foundation are pseudo-time steps towards equilibrium:
  // each extends the budget by one, up to twice max_iterations (past that a shorter time
  // step is cheaper).
  bool regularized_iterations_extend_budget = true;
  // Divergence: from the third iteration on, give up when the relative residual exceeds
  // divergence_ratio times that after the first iteration and divergence_floor (0 = never).
  double divergence_ratio = 1e3;
  double divergence_floor = 1e-3;
  // Stagnation, for callers that cut a failed step back (the cystometry): give up when the
  // smallest relative residual of the last stagnation_window iterations is above
  // stagnation_factor times the smallest before them (0 = never). A wall whose few elements
  // switch between taut, wrinkled and slack from one iterate to the next can hold its
  // residual on a plateau for dozens of iterations; the shorter step converges in a few.
  int stagnation_window = 8;
  double stagnation_factor = 0.0;
  // Tangent reuse (chord iterations): keep the last factorization while the residual falls
  // at least this fast, |r|_k ≤ ratio |r|_k−1 (0 = a fresh tangent every iteration:
  // quadratic convergence). A factorization of the indefinite K past the limit point costs
  // several assemblies, so a cystometry's time steps reuse it (RunOptions::newton).
  double reuse_tangent_ratio = 0.0;
  PreconditionedReuseOptions preconditioned_reuse;

  // Convergence. Each system tests what it has (NewtonSolver.h, FluidWallCoupling.h):
  double residual_tolerance = 1e-9;   // wall + cavity: |r| / gross force scale
  double increment_tolerance = 1e-8;  // both levels: max |Δx| of a wall node / model size
  double volume_tolerance = 1e-12;    // wall + cavity: |c| / V (the cavity equation)
  double pressure_tolerance = 1e-7;   // wall + urine: max |Δp| / max(|p|, 1 Pa)

  FoundationOptions foundation;
  LineSearchOptions line_search;
};

// The coupled wall–urine system's defaults (level 2): its convergence is tested on the
// increments only (positions to 1e-9 of the wall's size, pressures to 1e-7), with up to 40
// iterations, the foundation, and no line search, budget extension or divergence test
// (its Jacobian lags the interior mesh motion, so its residual does not fall monotonically).
inline NewtonOptions coupled_newton_options() {
  NewtonOptions o;
  o.max_iterations = 40;
  o.regularized_iterations_extend_budget = false;
  o.divergence_ratio = 0.0;
  o.increment_tolerance = 1e-9;
  o.pressure_tolerance = 1e-7;
  o.line_search.enabled = false;
  return o;
}

}  // namespace vesica::simulate
