#pragma once
// The study's results in one place (issue 9): one row per simulate stage of the plan (one
// per study run), holding the parameters the run set, its simulation outputs
// (summary.json, history.csv) and, when it has none or they say so, why it failed.
// to_csv() is study.csv; study_html() (StudyPage.h) draws the same rows.
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/pipelines/CystometryCurve.h"
#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/Runner.h"

namespace vesica::pipelines {

struct StudyRow {
  std::string variant;  // "" for the shared (non-study) run
  // "stage.param" -> value for the simulate stage and every stage it reads from, in
  // pipeline order (flags read "true").
  std::vector<std::pair<std::string, std::string>> parameters;
  std::filesystem::path simulation;      // the simulate stage's output folder
  nlohmann::json summary;                // summary.json, or null when absent
  std::filesystem::path history_csv;     // empty when absent
  std::optional<CystometryCurve> curve;  // history.csv, when it could be read
  std::string status = "not run";        // ok | failed | not run
  std::string failure;                   // why, when status is not ok
};

class StudyReport {
 public:
  // One row per stage of tool "simulate" in the plan. `run`, when given, is the run that
  // just happened: it names the failures of stages that left no summary.json.
  static StudyReport collect(const Plan& plan, const RunResult* run = nullptr);
  const std::vector<StudyRow>& rows() const { return rows_; }

  // study.csv: variant, status, the parameters that differ between runs, then
  // pdet_at_300ml_cmh2o, pdet_at_500ml_cmh2o, max_pdet_cmh2o, compliance_ml_per_cmh2o,
  // capacity_at_40cmh2o_ml (">V" when Pdet stayed below 40 up to the largest volume V),
  // qmax_ml_s, pvr_ml, max_wall_stress_kpa, failure. Empty cells: not reached / not run.
  std::string to_csv() const;
  // The column names (after variant and status) of the varied parameters.
  std::vector<std::string> varied_parameters() const;
  // The metric columns of one row, as printed in study.csv and study.html.
  static std::vector<std::pair<std::string, std::string>> metrics(const StudyRow& row);

 private:
  std::vector<StudyRow> rows_;
};

// Writes study.csv and study.html into the plan's workdir (atomically).
void write_study_outputs(const Plan& plan, const StudyReport& report);

}  // namespace vesica::pipelines
