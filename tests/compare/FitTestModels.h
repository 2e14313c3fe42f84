#pragma once
// Models with known answers for the calibration driver's tests: each turns parameter values
// into a recording the way vesica's cystometry would (a filling from 50 ml at 1 ml/s, then
// optionally a voiding), from a formula, so that the best fit is known without a simulator.
#include <cmath>
#include <functional>
#include <vector>

#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/calibration/CalibrationTargets.h"
#include "vesica/compare/calibration/ModelRun.h"

namespace vesica::test {

// Pdet(V) of a filling.
using FillingLaw = std::function<double(const std::vector<double>& p, double volume_ml)>;

// Rows every 5 ml from 50 ml to capacity_ml (1 ml/s); a run "fails" at stop_ml when that is
// below the capacity.
inline compare::ModelRun filling_run(const FillingLaw& law, const std::vector<double>& p,
                                     double capacity_ml, double stop_ml = 1e9) {
  compare::ModelRun run;
  auto& r = run.recording;
  for (double v = 50; v <= std::min(capacity_ml, stop_ml) + 1e-9; v += 5) {
    r.time_s.push_back(v - 50);
    r.volume_ml.push_back(v);
    r.infused_ml.push_back(v - 50);
    r.pdet_recorded_cmh2o.push_back(law(p, v));
  }
  run.completed = stop_ml >= capacity_ml;
  if (!run.completed) run.failure = "step failed at V = " + std::to_string(stop_ml) + " ml";
  return run;
}

// A measured filling: rows every 25 ml from 50 to 350 ml with Pdet(V).
inline compare::RecordingAnalysis measured_filling(const std::function<double(double)>& pdet) {
  compare::Recording r;
  r.source = "synthetic";
  for (double v = 50; v <= 350; v += 25) {
    r.time_s.push_back(v);
    r.infused_ml.push_back(v);
    r.pdet_recorded_cmh2o.push_back(pdet(v));
  }
  return compare::analyse(r);
}

}  // namespace vesica::test
