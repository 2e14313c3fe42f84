#pragma once
// Hook for issue 9's study.csv / study.html: collects, per study run, the parameters it
// set and the simulate stage's summary.json and history.csv when they exist. The tables
// and plots themselves come later; this gathers the data in one place.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

struct StudyRow {
  std::string variant;                // "" for the shared (non-study) run
  std::vector<Param> parameters;      // parameters of the simulate stage copy
  std::filesystem::path simulation;   // the simulate stage's output folder
  nlohmann::json summary;             // summary.json, or null when not run yet
  std::filesystem::path history_csv;  // empty when not run yet
};

class StudyReport {
 public:
  // One row per stage of tool "simulate" in the plan.
  static StudyReport collect(const Plan& plan);
  const std::vector<StudyRow>& rows() const { return rows_; }
  // variant,<summary keys...> — numbers from each summary.json (first-level scalars).
  std::string to_csv() const;

 private:
  std::vector<StudyRow> rows_;
};

}  // namespace vesica::pipelines
