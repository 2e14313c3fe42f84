#include "vesica/pipelines/StudyMetrics.h"

namespace vesica::pipelines {

const std::vector<StudyMetric>& study_metrics() {
  static const std::vector<StudyMetric> metrics = {
      {"built_volume_ml", "built volume", "ml"},
      {"pdet_at_300ml_cmh2o", "Pdet at 300 ml", "cmH2O"},
      {"pdet_at_500ml_cmh2o", "Pdet at 500 ml", "cmH2O"},
      {"max_pdet_cmh2o", "max Pdet", "cmH2O"},
      {"compliance_ml_per_cmh2o", "compliance", "ml/cmH2O"},
      {"capacity_at_40cmh2o_ml", "volume at 40 cmH2O", "ml"},
      {"qmax_ml_s", "Qmax", "ml/s"},
      {"voided_ml", "voided", "ml"},
      {"pvr_ml", "residual (PVR)", "ml"},
      {"stress_p95_at_capacity_kpa", "wall stress at capacity, 95th pct", "kPa"},
      {"stress_max_at_capacity_kpa", "wall stress at capacity, max", "kPa"},
  };
  return metrics;
}

const StudyMetric* find_study_metric(const std::string& key) {
  for (const StudyMetric& m : study_metrics())
    if (key == m.key) return &m;
  return nullptr;
}

std::vector<std::string> study_metric_keys() {
  std::vector<std::string> keys;
  for (const StudyMetric& m : study_metrics()) keys.emplace_back(m.key);
  return keys;
}

}  // namespace vesica::pipelines
