#pragma once
// Model against measurement: the filling curves Pdet(V) on a common volume grid over the
// volumes both cover, the differences of the ICS parameters, and the voiding curves V(t)
// and Q(t) on a common time grid from the onset of flow.
#include <optional>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vesica/compare/analysis/IcsParameters.h"
#include "vesica/compare/recording/Recording.h"

namespace vesica::compare {

struct ComparisonOptions {
  // Restrict the filling comparison to these volumes (ml), intersected with the overlap.
  std::optional<std::pair<double, double>> volume_range_ml;
  double volume_step_ml = 5.0;
  double time_step_s = 0.5;
};

struct CurveDifference {
  std::vector<double> grid, measured, simulated;  // on the common grid
  double lo = 0, hi = 0;                          // the grid's extent
  std::optional<double> rmse, max_abs_error;      // none when the curves do not overlap
  std::vector<double> residuals() const;          // simulated - measured
};

// Pdet(V): grid over [max of the minima, min of the maxima] ∩ volume_range_ml.
CurveDifference compare_curves(const Curve& measured, const Curve& simulated, double lo_limit,
                               double hi_limit, double step);
CurveDifference compare_filling(const Curve& measured, const Curve& simulated,
                                const ComparisonOptions& options);

// Voided volume and flow against time since the onset of flow.
struct VoidingCurves {
  Curve voided_ml, flow_ml_s;
};
VoidingCurves voiding_curves(const Recording& recording, const IcsParameters& p);

// Every model-vs-measured number, in one JSON object (metrics.json "comparison").
nlohmann::json compare_models(const Recording& measured, const IcsParameters& measured_ics,
                              const Curve& measured_filling, const Recording& simulated,
                              const IcsParameters& simulated_ics, const Curve& simulated_filling,
                              const ComparisonOptions& options);

}  // namespace vesica::compare
