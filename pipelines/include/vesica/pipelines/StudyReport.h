#pragma once
// The study's results in one place (issue 9): one row per simulate stage of the plan (one
// per study run), holding the parameters the run set, its simulation outputs
// (summary.json, history.csv, the wall stress of its series at capacity) and, when it has
// none or they say so, why it failed; and the answer of each row to the study's design
// question (the `limits:` of the study file, StudyAnswer.h).
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
#include "vesica/pipelines/StudyAnswer.h"

namespace vesica::pipelines {

struct StudyRow {
  std::string variant;  // "" for the shared (non-study) run
  // "stage.param" -> value for the simulate stage and every stage it reads from, in
  // pipeline order (flags read "true").
  std::vector<std::pair<std::string, std::string>> parameters;
  std::filesystem::path simulation;       // the simulate stage's output folder
  nlohmann::json summary;                 // summary.json, or null when absent
  std::filesystem::path history_csv;      // empty when absent
  std::optional<CystometryCurve> curve;   // history.csv, when it could be read
  nlohmann::json capacity_stress;         // CapacityStress.h, null without a series
  std::optional<double> built_volume_ml;  // the surface stage's report: the pouch as built
  std::string status = "not run";         // ok | failed | not run
  std::string failure;                    // why, when status is not ok
};

class StudyReport {
 public:
  // One row per stage of tool "simulate" in the plan. `run`, when given, is the run that
  // just happened: it names the failures of stages that left no summary.json.
  static StudyReport collect(const Plan& plan, const RunResult* run = nullptr);
  const std::vector<StudyRow>& rows() const { return rows_; }

  // study.csv: variant, status, answer (pass | fail | empty), the parameters that differ
  // between runs, then the read-outs of StudyMetrics.h: built_volume_ml, pdet_at_300ml_cmh2o,
  // pdet_at_500ml_cmh2o, max_pdet_cmh2o, compliance_ml_per_cmh2o, capacity_at_40cmh2o_ml
  // (">V" when Pdet stayed below 40 up to the largest volume V), qmax_ml_s, voided_ml, pvr_ml,
  // stress_p95_at_capacity_kpa, stress_max_at_capacity_kpa; then stress_max_where and
  // failure. Empty cells: not reached / not run.
  std::string to_csv() const;
  // The column names (after variant, status and answer) of the varied parameters.
  std::vector<std::string> varied_parameters() const;
  // The varied parameters less those that only repeat an earlier one (each value of one
  // goes with one value of the other: a pouch's residual and start volume with its built
  // volume); `repeats` gets (dropped, the one it follows).
  std::vector<std::string> distinct_parameters(
      std::vector<std::pair<std::string, std::string>>* repeats = nullptr) const;
  std::string parameter(const StudyRow& row, const std::string& key) const;
  // The read-outs of one row, in StudyMetrics.h's order.
  static StudyValues values(const StudyRow& row);
  // The read-outs as printed in study.csv (6 significant digits, ">V" for a lower bound).
  static std::vector<std::pair<std::string, std::string>> metrics(const StudyRow& row);
  // The design question and its limits, and one row's answer to it.
  const std::string& question() const { return question_; }
  const std::vector<StudyLimit>& limits() const { return limits_; }
  std::string answer(const StudyRow& row) const;

 private:
  std::vector<StudyRow> rows_;
  std::string question_;
  std::vector<StudyLimit> limits_;
};

// Writes study.csv and study.html into the plan's workdir (atomically).
void write_study_outputs(const Plan& plan, const StudyReport& report);

}  // namespace vesica::pipelines
