#pragma once
// The read-outs a study reports per variant (the numeric columns of study.csv), with the
// words and unit the page prints. A study's `limits:` name them (PipelineFile.h), so the
// pipeline file is checked against this list.
#include <optional>
#include <string>
#include <vector>

namespace vesica::pipelines {

struct StudyMetric {
  const char* key;    // study.csv column, unit in the name
  const char* label;  // the page's column heading
  const char* unit;
};

// One read-out of one variant: a number, a lower bound ("above": the volume at 40 cmH2O
// when filling never reached 40), or nothing (not reached, not run).
struct StudyValue {
  std::optional<double> value;
  bool above = false;
};

// In column order.
const std::vector<StudyMetric>& study_metrics();
const StudyMetric* find_study_metric(const std::string& key);
std::vector<std::string> study_metric_keys();

}  // namespace vesica::pipelines
