#pragma once
// When a recording's filling started and at what mean rate, from its infused-volume
// channel, so that a measured and a simulated recording can share one time axis ("time
// since the start of filling") and the report can state the fill rate it actually saw.
#include <optional>

#include "vesica/compare/analysis/IcsParameters.h"
#include "vesica/compare/recording/Recording.h"

namespace vesica::compare {

struct FillingTimes {
  double start_s = 0.0;  // the moment infusion began (s, the recording's own clock)
  std::optional<double> mean_rate_ml_min;
};

// Mean rate: infused volume from the first row with infusion to capacity over the time
// between them. Start: that first row's time less its infused volume at the mean rate
// (clinical exports often begin mid-infusion), never before the row ahead of it; the first
// row when there is no infused channel; 0 and no rate for a table without time.
FillingTimes filling_times(const Recording& r, const IcsParameters& p);

}  // namespace vesica::compare
