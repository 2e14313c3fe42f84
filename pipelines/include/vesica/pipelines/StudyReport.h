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
  std::string stage;    // the simulate stage's name in the file
  // A run at an end of the study's uncertainty (PipelineFile.h): the end's name, and the
  // run it bounds ("" for the shared run). Empty for an ordinary row.
  std::string bound;
  std::string bound_of;
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
  // The ordinary rows: one per run of the study, in plan order.
  const std::vector<StudyRow>& rows() const { return rows_; }
  // The rows at the ends of the uncertainty that bound `row`, in the study file's order of
  // the ends; empty without `uncertainty:`.
  std::vector<const StudyRow*> bounds_of(const StudyRow& row) const;
  // The names of the uncertainty's ends, in the study file's order.
  const std::vector<std::string>& uncertainty_ends() const { return ends_; }
  // A row's name on the page and in messages: its run, or its stage when shared.
  std::string label(const StudyRow& row) const;

  // study.csv: variant, status, answer (pass | fail | empty), with uncertainty ends the
  // end a row is at (its `uncertainty` column, empty for an ordinary row, each ordinary row
  // followed by its ends' rows), the parameters that differ
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
  std::vector<std::string> varied_over(const std::vector<const StudyRow*>& rows) const;

  std::vector<StudyRow> rows_;
  std::vector<StudyRow> bound_rows_;
  std::vector<std::string> ends_;
  std::string question_;
  std::vector<StudyLimit> limits_;
};

// Writes study.csv and study.html into the plan's workdir (atomically).
void write_study_outputs(const Plan& plan, const StudyReport& report);

}  // namespace vesica::pipelines
