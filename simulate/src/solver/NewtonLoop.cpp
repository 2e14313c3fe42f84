#include "solver/NewtonLoop.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <utility>

#include "solver/StopRequest.h"

namespace vesica::simulate {

NewtonLoop::NewtonLoop(const NewtonOptions& options, ElasticFoundation foundation)
    : options_(options), foundation_(std::move(foundation)) {}

void NewtonLoop::reset() {
  eta_ = 0.0;
  tangent_reusable_ = false;
}

int NewtonLoop::budget(const NewtonReport& report) const {
  if (!options_.regularized_iterations_extend_budget) return options_.max_iterations;
  return std::min(options_.max_iterations + report.regularized_iterations,
                  2 * options_.max_iterations);
}

bool NewtonLoop::diverging(const NewtonReport& report, int iteration) const {
  if (options_.divergence_ratio <= 0.0 || iteration < 3) return false;
  const double r = report.residual_norms[iteration];
  return r > options_.divergence_ratio * report.residual_norms[1] && r > options_.divergence_floor;
}

// The residual norms hold one entry per iteration up to `iteration`.
bool NewtonLoop::stagnating(const NewtonReport& report, int iteration) const {
  const int window = options_.stagnation_window;
  if (options_.stagnation_factor <= 0.0 || window <= 0 || iteration <= window) return false;
  const auto& r = report.residual_norms;
  const auto recent = r.begin() + (iteration - window + 1);
  const double best_before = *std::min_element(r.begin(), recent);
  const double best_recent = *std::min_element(recent, r.begin() + iteration + 1);
  return best_recent > options_.stagnation_factor * best_before;
}

NewtonReport NewtonLoop::solve(NewtonSystem& system) {
  NewtonReport report;
  double last_move = INFINITY;
  bool reusable = tangent_reusable_;
  tangent_reusable_ = false;  // until this solve converges
  bool evaluated = false;     // the line search of the last iteration evaluated the iterate
  const bool tests_residual = system.tests_residual();
  for (int it = 0;; ++it) {
    report.iterations = it;
    if (stop_requested()) {  // a stop within one iteration, not at the end of the step
      report.failure = "stopped by a signal";
      return report;
    }
    const bool increment_ok = system.increment_converged(it, last_move);
    if (!tests_residual && (increment_ok || it == budget(report))) {
      report.converged = increment_ok;
      break;
    }
    try {
      if (!evaluated) system.evaluate();
      evaluated = false;
      bool equilibrium = false;
      if (tests_residual) {
        const ResidualCheck check = system.check_residual();
        report.residual_norms.push_back(check.norm);
        if (!check.failure.empty()) {
          report.failure = check.failure;
          return report;
        }
        if (check.converged && increment_ok) {
          report.converged = true;
          break;
        }
        if (it == budget(report)) break;
        if (diverging(report, it)) {
          report.failure = "Newton iteration diverges";
          return report;
        }
        if (stagnating(report, it)) {
          report.failure = "Newton iteration stagnates";
          return report;
        }
        equilibrium = check.equilibrium;
      }
      if (system.unknown_count() == 0) break;
      // Tangent reuse (modified Newton): with the wall already in equilibrium only a small
      // correction is left, and the last tangent, from this solve or the converged state of
      // the previous one, serves it as well as a new factorization; optionally also while
      // the residual falls fast (chord iterations), or always as the preconditioner of the
      // current tangent, which falls back to a new factorization itself where it does not
      // serve. Never on the foundation.
      const auto& norms = report.residual_norms;
      const bool converging_fast = it >= 1 && norms.size() > static_cast<std::size_t>(it) &&
                                   norms[it] <= options_.reuse_tangent_ratio * norms[it - 1];
      const bool preconditioned = options_.preconditioned_reuse.max_iterations > 0;
      const bool reuse =
          (equilibrium || converging_fast || preconditioned) && reusable && eta_ == 0.0;
      double move = regularized_increment(system, reuse, reusable, report);
      if (!report.failure.empty()) {
        report.iterations = it + 1;
        return report;
      }
      if (options_.line_search.enabled && system.line_search_applies() && it > 0)
        move *= line_search(system, evaluated);
      else
        system.apply_increment();
      last_move = move;
    } catch (const std::exception& e) {
      // The iterate was not admissible or its solve failed: this iteration counts.
      report.iterations = it + 1;
      report.failure = e.what();
      return report;
    }
  }
  if (report.converged) {
    tangent_reusable_ = reusable;
  } else if (report.failure.empty()) {
    report.failure = "no convergence in " + std::to_string(report.iterations) + " iterations";
  }
  return report;
}

// A step that would move a wall node further than the limit is recomputed with the
// foundation η A, η raised until the step is short enough (NewtonOptions.h); η then decays
// into the next iteration.
double NewtonLoop::regularized_increment(NewtonSystem& system, bool reuse, bool& reusable,
                                         NewtonReport& report) {
  const FoundationOptions& f = foundation_.options();
  const double max_move = foundation_.max_move() + system.demanded_move();
  Eigen::SparseMatrix<double>& K = system.tangent();
  const double scale = foundation_.stiffness_scale(K);
  double eta = eta_, eta_in_K = 0.0, move = 0.0;
  for (int raise = 0;; ++raise) {
    if (eta != eta_in_K) {
      foundation_.add(K, eta - eta_in_K);
      eta_in_K = eta;
    }
    if (!system.solve_increment(reuse && raise == 0, report.failure)) return 0.0;
    reusable = system.factorization_reusable();
    move = system.increment_move();
    if (max_move <= 0.0 || move <= max_move || raise == f.max_raises) break;
    eta = eta > 0.0 ? f.raise_factor * eta : f.first_stiffness * scale;
  }
  if (eta > 0.0) ++report.regularized_iterations;
  eta_ = eta > f.off_below * scale ? f.decay_factor * eta : 0.0;
  return move;
}

double NewtonLoop::line_search(NewtonSystem& system, bool& evaluated) const {
  const double merit0 = system.begin_line_search();
  double fraction = 1.0;
  for (int halving = 0;; ++halving, fraction *= 0.5) {
    double merit = 0.0;
    const bool admissible = system.try_fraction(fraction, merit);
    if ((admissible && merit < merit0) || halving == options_.line_search.max_halvings) {
      // Not admissible even at the shortest step: the next iteration's evaluation says why.
      evaluated = admissible;
      if (admissible) system.keep_trial();
      return fraction;
    }
  }
}

}  // namespace vesica::simulate
