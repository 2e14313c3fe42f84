#pragma once
// The Newton work of a cavity model's steps, as the summary reports it ("newton"): each
// model counts by its own rules (which attempts' iterations count, what a cut-back is).
#include <algorithm>

#include <nlohmann/json.hpp>

namespace vesica::simulate {

struct StepStatistics {
  int steps = 0;           // converged steps
  int iterations = 0;      // Newton iterations
  int cutbacks = 0;        // halved steps
  int max_iterations = 0;  // of one converged step

  void converged_step(int step_iterations) {
    ++steps;
    max_iterations = std::max(max_iterations, step_iterations);
  }
  nlohmann::json json() const {
    return {{"steps", steps},
            {"iterations", iterations},
            {"cutbacks", cutbacks},
            {"max_iterations_per_step", max_iterations},
            {"mean_iterations_per_step", steps ? double(iterations) / steps : 0.0}};
  }
};

}  // namespace vesica::simulate
