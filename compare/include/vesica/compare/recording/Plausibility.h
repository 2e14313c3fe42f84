#pragma once
// What a measured recording must look like to be read as its column names say
// (docs/compare.md, "Plausibility rules"). A file whose numbers cannot be what their units
// claim (pressures in Pa or kPa labelled cmH2O, flow in ml/min labelled ml/s, a negative
// voided volume, far more voided than infused) would otherwise give confident nonsense:
// Pdet 2550 cmH2O, a compliance of 1101 ml/cmH2O, Qmax 1020 ml/s, a voiding efficiency of
// -1. Each rule has a name and a threshold; a clear breach is a refusal (vesica::Error
// naming the file and the rule), a milder one a warning the report and metrics.json carry.
#include <string>
#include <vector>

#include "vesica/compare/recording/Recording.h"

namespace vesica::compare {

struct PlausibilityWarning {
  std::string rule;     // "flow-voided-mismatch"
  std::string message;  // one sentence with the numbers
};

// Thresholds of the rules (clinical units).
struct PlausibilityLimits {
  double max_pressure_p95_cmh2o = 200;       // pressure-in-pa: 95th percentile of |p|
  double max_pressure_cmh2o = 500;           // pressure-in-pa: any |p|
  double min_pves_max_cmh2o = 5;             // pressure-in-kpa: Pves never above this
  double max_compliance_ml_per_cmh2o = 500;  // compliance (warning)
  double max_qmax_ml_s = 100;                // flow-in-ml-min (refusal)
  double high_qmax_ml_s = 50;                // flow-in-ml-min (warning)
  double min_volume_ml = -1;                 // negative-volume: voided or infused below
  double voided_over_infused_factor = 2;     // voided-exceeds-infused (refusal): factor x infused
  double voided_over_infused_ml = 100;       //   + this
  double excess_voided_ml = 50;              // voided-exceeds-infused (warning): infused + this
  double flow_voided_ratio = 2;              // flow-voided-mismatch (warning): outside [1/r, r]
};

// Throws vesica::Error naming the recording's file for a refusal; returns the warnings.
// `compliance_ml_per_cmh2o` is the ICS compliance computed from it, when there is one.
std::vector<PlausibilityWarning> check_plausibility(const Recording& recording,
                                                    const PlausibilityLimits& limits = {});

// The compliance rule, once the ICS parameters are known: a warning, or nothing.
std::vector<PlausibilityWarning> check_compliance(double compliance_ml_per_cmh2o,
                                                  const PlausibilityLimits& limits = {});

}  // namespace vesica::compare
