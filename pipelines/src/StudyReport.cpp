#include "vesica/pipelines/StudyReport.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
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

std::string number(const std::optional<double>& v) {
  return v ? number(*v) : "";
}

std::string summary_number(const nlohmann::json& summary, const char* key) {
  if (!summary.is_object() || !summary.contains(key) || !summary[key].is_number()) return "";
  return number(summary[key].get<double>());
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

void read_outputs(StudyRow& row) {
  std::ifstream in(row.simulation / "summary.json");
  if (in) row.summary = nlohmann::json::parse(in, nullptr, false);
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
    const std::vector<std::size_t> chain = chain_of(plan, i);
    for (std::size_t c : chain)
      for (const Param& p : plan.stages[c].params)
        if (p.kind != Param::Kind::Omitted)
          row.parameters.emplace_back(plan.stages[c].stage + "." + p.key,
                                      p.kind == Param::Kind::Flag ? "true" : p.value);
    row.simulation = plan.in_workdir(s.output);
    read_outputs(row);
    decide_status(row, run ? failure_in_run(*run, chain) : "");
    report.rows_.push_back(std::move(row));
  }
  return report;
}

std::vector<std::string> StudyReport::varied_parameters() const {
  std::vector<std::string> keys;
  for (const auto& r : rows_)
    for (const auto& [k, v] : r.parameters)
      if (std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  std::vector<std::string> varied;
  for (const auto& k : keys) {
    std::set<std::string> values;
    for (const auto& r : rows_) {
      std::string value = "<unset>";
      for (const auto& [rk, rv] : r.parameters)
        if (rk == k) value = rv;
      values.insert(value);
    }
    if (values.size() > 1) varied.push_back(k);
  }
  return varied;
}

std::vector<std::pair<std::string, std::string>> StudyReport::metrics(const StudyRow& row) {
  const CystometryCurve empty;
  const CystometryCurve& c = row.curve ? *row.curve : empty;
  std::string capacity = number(filling_volume_at_pdet(c, kCapacityPdetCmh2o));
  if (capacity.empty() && c.size() > 0) capacity = ">" + number(c.volume_ml[c.filling_end()]);
  return {{"pdet_at_300ml_cmh2o", number(filling_pdet_at_volume(c, kLowVolumeMl))},
          {"pdet_at_500ml_cmh2o", number(filling_pdet_at_volume(c, kHighVolumeMl))},
          {"max_pdet_cmh2o", number(max_pdet(c))},
          {"compliance_ml_per_cmh2o", number(filling_compliance(c))},
          {"capacity_at_40cmh2o_ml", capacity},
          {"qmax_ml_s", number(voiding_qmax(c))},
          // A residual only when voiding ran to its end (a failed run's summary counts
          // the volume where it stopped).
          {"pvr_ml", row.status == "ok" ? summary_number(row.summary, "pvr_ml") : ""},
          {"max_wall_stress_kpa", summary_number(row.summary, "max_wall_stress_kpa")}};
}

std::string StudyReport::to_csv() const {
  const std::vector<std::string> varied = varied_parameters();
  std::string csv = "variant,status";
  for (const auto& k : varied) csv += "," + csv_cell(k);
  for (const auto& [name, value] : metrics(StudyRow{})) csv += "," + name;
  csv += ",failure\n";
  for (const auto& r : rows_) {
    csv += csv_cell(r.variant) + "," + r.status;
    for (const auto& k : varied) {
      std::string value;
      for (const auto& [rk, rv] : r.parameters)
        if (rk == k) value = rv;
      csv += "," + csv_cell(value);
    }
    for (const auto& [name, value] : metrics(r)) csv += "," + csv_cell(value);
    csv += "," + csv_cell(r.status == "ok" ? "" : r.failure) + "\n";
  }
  return csv;
}

void write_study_outputs(const Plan& plan, const StudyReport& report) {
  write_text_atomically(plan.workdir / "study.csv", report.to_csv());
  write_text_atomically(plan.workdir / "study.html", study_html(report, plan.name));
}

}  // namespace vesica::pipelines
