#include "vesica/pipelines/StudyReport.h"

#include <algorithm>
#include <cstdio>
#include <set>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/JsonFile.h"
#include "vesica/core/Log.h"
#include "vesica/pipelines/CapacityStress.h"
#include "vesica/pipelines/StudyPage.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

// The study's fixed read-outs (issue 9): Pdet at these volumes, capacity at this pressure.
constexpr double kLowVolumeMl = 300.0;
constexpr double kHighVolumeMl = 500.0;
constexpr double kCapacityPdetCmh2o = 40.0;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::optional<double> json_number(const nlohmann::json& j, const char* key) {
  if (!j.is_object() || !j.contains(key) || !j[key].is_number()) return std::nullopt;
  return j[key].get<double>();
}

std::string cell(const StudyValue& v) {
  return v.value ? (v.above ? ">" : "") + number(*v.value) : "";
}

// A CSV cell: quoted when it holds a comma, a quote or a line break.
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

// The simulate stage and every stage it depends on, in plan order.
std::vector<std::size_t> chain_of(const Plan& plan, std::size_t index) {
  std::set<std::size_t> seen = {index};
  std::vector<std::size_t> todo = {index};
  while (!todo.empty()) {
    const std::size_t i = todo.back();
    todo.pop_back();
    for (std::size_t d : plan.stages[i].deps)
      if (seen.insert(d).second) todo.push_back(d);
  }
  return {seen.begin(), seen.end()};
}

// Why a simulation has no results, from the run that just happened: its own failure or
// the failure of a stage it reads from.
std::string failure_in_run(const RunResult& run, const std::vector<std::size_t>& chain) {
  for (std::size_t i : chain) {
    const StageOutcome& o = run.stages[i];
    if (o.action == "failed")  // a stage killed by a signal may print nothing
      return o.id + " failed (exit " + std::to_string(o.exit_code) + ")" +
             (o.last_line.empty() ? "" : ": " + o.last_line);
  }
  return "";
}

// The volume of the surface the simulation's chain built (its stage report's volume_ml,
// ml): the pouch as the surgeon made it, before the simulation scales its reference.
void read_built_volume(const Plan& plan, const std::vector<std::size_t>& chain, StudyRow& row) {
  for (std::size_t c : chain) {
    const PlannedStage& s = plan.stages[c];
    if (s.tool != "surface" || s.report.empty()) continue;
    const nlohmann::json report =
        read_json_file(plan.in_workdir(s.report)).value_or(nlohmann::json());
    row.built_volume_ml = json_number(report, "volume_ml");
  }
}

// The wall stress at capacity, asked of vesica-compare beside the simulate executable.
void read_capacity_stress(const PlannedStage& simulate, StudyRow& row) {
  if (row.status != "ok") return;
  std::string why;
  row.capacity_stress =
      capacity_stress(simulate.executable.parent_path() / "vesica-compare", row.simulation, why);
  if (!why.empty()) log()->warn("{}: no wall stress at capacity: {}", row.variant, why);
}

void read_outputs(StudyRow& row) {
  try {
    row.summary = read_json_file(row.simulation / "summary.json").value_or(nullptr);
  } catch (const Error& e) {
    row.failure = e.what();
  }
  if (row.summary.is_discarded()) row.summary = nullptr;
  if (!fs::exists(row.simulation / "history.csv")) return;
  row.history_csv = row.simulation / "history.csv";
  try {
    row.curve = read_history_csv(row.history_csv);
  } catch (const Error& e) {
    row.failure = e.what();
  }
}

void decide_status(StudyRow& row, const std::string& failure_this_run) {
  if (row.summary.is_object() && row.summary.value("completed", true) == false) {
    row.status = "failed";
    row.failure = row.summary.value("failure", std::string("simulation did not complete"));
  } else if (!failure_this_run.empty()) {
    row.status = "failed";  // outputs, if any, are from an earlier run
    row.failure = failure_this_run;
  } else if (row.summary.is_object() && row.curve) {
    row.status = "ok";
  } else if (row.failure.empty()) {
    row.failure = "no summary.json yet";
  }
}

}  // namespace

StudyReport StudyReport::collect(const Plan& plan, const RunResult* run) {
  StudyReport report;
  for (std::size_t i = 0; i < plan.stages.size(); ++i) {
    const PlannedStage& s = plan.stages[i];
    if (s.tool != "simulate") continue;
    StudyRow row;
    row.variant = s.variant;
    row.stage = s.stage;
    row.bound = s.bound;
    row.bound_of = s.bound_of;
    const std::vector<std::size_t> chain = chain_of(plan, i);
    for (std::size_t c : chain)
      for (const Param& p : plan.stages[c].params)
        if (p.kind != Param::Kind::Omitted)
          row.parameters.emplace_back(plan.stages[c].stage + "." + p.key,
                                      p.kind == Param::Kind::Flag ? "true" : p.value);
    row.simulation = plan.in_workdir(s.output);
    read_outputs(row);
    decide_status(row, run ? failure_in_run(*run, chain) : "");
    read_capacity_stress(s, row);
    read_built_volume(plan, chain, row);
    if (!row.bound.empty() &&
        std::find(report.ends_.begin(), report.ends_.end(), row.bound) == report.ends_.end())
      report.ends_.push_back(row.bound);
    (row.bound.empty() ? report.rows_ : report.bound_rows_).push_back(std::move(row));
  }
  report.question_ = plan.question;
  report.limits_ = plan.limits;
  return report;
}

std::vector<const StudyRow*> StudyReport::bounds_of(const StudyRow& row) const {
  std::vector<const StudyRow*> out;
  if (!row.bound.empty()) return out;
  for (const std::string& end : ends_)
    for (const StudyRow& b : bound_rows_)
      if (b.bound == end && b.bound_of == row.variant && b.stage == row.stage) out.push_back(&b);
  return out;
}

std::string StudyReport::label(const StudyRow& row) const {
  if (!row.variant.empty()) return row.variant;
  // A stage every run shares is named by the stage when it sits among the runs' rows.
  return rows_.size() > 1 ? row.stage : "(shared)";
}

std::vector<std::string> StudyReport::varied_over(const std::vector<const StudyRow*>& rows) const {
  std::vector<std::string> keys;
  for (const StudyRow* r : rows)
    for (const auto& [k, v] : r->parameters)
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  std::vector<std::string> varied;
  for (const auto& k : keys) {
    std::set<std::string> values;
    for (const StudyRow* r : rows) {
      std::string value = "<unset>";
      for (const auto& [rk, rv] : r->parameters)
        if (rk == k) value = rv;
      values.insert(r->stage + "|" + value);
    }
    // A parameter of one simulate stage only varies when it varies among that stage's rows.
    std::set<std::string> stages;
    for (const StudyRow* r : rows) stages.insert(r->stage);
    if (values.size() > stages.size()) varied.push_back(k);
  }
  return varied;
}

std::vector<std::string> StudyReport::varied_parameters() const {
  std::vector<const StudyRow*> rows;
  for (const StudyRow& r : rows_) rows.push_back(&r);
  return varied_over(rows);
}

std::vector<std::string> StudyReport::distinct_parameters(
    std::vector<std::pair<std::string, std::string>>* repeats) const {
  // a and b repeat each other when equal values of a go with equal values of b and back
  auto same_partition = [&](const std::string& a, const std::string& b) {
    for (const auto& r1 : rows_)
      for (const auto& r2 : rows_)
        if ((parameter(r1, a) == parameter(r2, a)) != (parameter(r1, b) == parameter(r2, b)))
          return false;
    return true;
  };
  std::vector<std::string> kept;
  for (const auto& k : varied_parameters()) {
    const auto first = std::find_if(kept.begin(), kept.end(),
                                    [&](const std::string& e) { return same_partition(e, k); });
    if (first == kept.end())
      kept.push_back(k);
    else if (repeats)
      repeats->emplace_back(k, *first);
  }
  return kept;
}

std::string StudyReport::parameter(const StudyRow& row, const std::string& key) const {
  for (const auto& [k, v] : row.parameters)
    if (k == key) return v;
  return "";
}

StudyValues StudyReport::values(const StudyRow& row) {
  const CystometryCurve empty;
  const CystometryCurve& c = row.curve ? *row.curve : empty;
  StudyValue capacity{filling_volume_at_pdet(c, kCapacityPdetCmh2o)};
  if (!capacity.value && c.size() > 0) capacity = {c.volume_ml[c.filling_end()], true};
  const nlohmann::json stress =
      row.capacity_stress.is_object() ? row.capacity_stress["summary"] : nlohmann::json();
  const bool voided = row.status == "ok";
  return {{"built_volume_ml", {row.built_volume_ml}},
          {"pdet_at_300ml_cmh2o", {filling_pdet_at_volume(c, kLowVolumeMl)}},
          {"pdet_at_500ml_cmh2o", {filling_pdet_at_volume(c, kHighVolumeMl)}},
          {"max_pdet_cmh2o", {max_pdet(c)}},
          {"compliance_ml_per_cmh2o", {filling_compliance(c)}},
          {"capacity_at_40cmh2o_ml", capacity},
          {"qmax_ml_s", {voiding_qmax(c)}},
          // A residual only when voiding ran to its end (a failed run's summary counts
          // the volume where it stopped).
          {"voided_ml", {voided ? json_number(row.summary, "voided_ml") : std::nullopt}},
          {"pvr_ml", {voided ? json_number(row.summary, "pvr_ml") : std::nullopt}},
          // At capacity, not the largest of any frame: a voiding collapse puts one-element
          // spikes into late frames.
          {"stress_p95_at_capacity_kpa", {json_number(stress, "p95_kpa")}},
          {"stress_max_at_capacity_kpa", {json_number(stress, "max_kpa")}}};
}

std::vector<std::pair<std::string, std::string>> StudyReport::metrics(const StudyRow& row) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [key, value] : values(row)) out.emplace_back(key, cell(value));
  return out;
}

std::string StudyReport::answer(const StudyRow& row) const {
  return row.status == "ok" ? pipelines::answer(limits_, values(row)) : "";
}

namespace {

std::string where_of(const StudyRow& row) {
  if (!row.capacity_stress.is_object()) return "";
  return row.capacity_stress["summary"].value("where", "");
}

}  // namespace

std::string StudyReport::to_csv() const {
  std::vector<const StudyRow*> all;
  for (const StudyRow& r : rows_) {
    all.push_back(&r);
    for (const StudyRow* b : bounds_of(r)) all.push_back(b);
  }
  const std::vector<std::string> varied = varied_over(all);
  const bool ends = !ends_.empty();
  std::string csv = std::string("variant,status,answer") + (ends ? ",uncertainty" : "");
  for (const auto& k : varied) csv += "," + csv_cell(k);
  for (const auto& m : study_metrics()) csv += std::string(",") + m.key;
  csv += ",stress_max_where,failure\n";
  for (const StudyRow* row : all) {
    const StudyRow& r = *row;
    csv += csv_cell(r.variant.empty() && rows_.size() > 1 ? r.stage : r.variant) + "," + r.status +
           "," + answer(r);
    if (ends) csv += "," + csv_cell(r.bound);
    for (const auto& k : varied) csv += "," + csv_cell(parameter(r, k));
    for (const auto& [name, value] : metrics(r)) csv += "," + csv_cell(value);
    csv += "," + csv_cell(where_of(r));
    csv += "," + csv_cell(r.status == "ok" ? "" : r.failure) + "\n";
  }
  return csv;
}

void write_study_outputs(const Plan& plan, const StudyReport& report) {
  write_text_atomically(plan.workdir / "study.csv", report.to_csv());
  write_text_atomically(plan.workdir / "study.html", study_html(report, plan.name));
}

}  // namespace vesica::pipelines
