#pragma once
// The settings of the Newton iteration of a cystometry's steps (NewtonSolver).
namespace vesica::simulate {

struct NewtonOptions {
  int max_iterations = 15;
  double residual_tolerance = 1e-9;   // |r| / force scale
  double increment_tolerance = 1e-8;  // |Δu|∞ / model size
  double volume_tolerance = 1e-12;    // |c| / V
  // Largest node move of one iteration, as a fraction of the mean reference edge. A
  // stress-free or slack membrane has (nearly) no stiffness against bending-like modes,
  // so a plain Newton step there moves nodes by orders of magnitude too far; a longer
  // step is instead shortened by the elastic-foundation regularization below.
  double max_move_per_edge = 0.5;  // 0 = off
  // Halve a step of a wrinkling wall that would raise its residuals (NewtonSolver.cpp).
  bool line_search = true;
  // Chord iterations: keep the last factorization while the residual falls at least this
  // fast, |r|_k ≤ ratio |r|_k-1 (0 = a fresh tangent every iteration: quadratic
  // convergence). A factorization of the indefinite K past the limit point (sparse LU) costs
  // four assemblies, so a cystometry's time steps reuse it (RunOptions, ratio 0.1).
  double reuse_tangent_ratio = 0.0;
};

}  // namespace vesica::simulate
