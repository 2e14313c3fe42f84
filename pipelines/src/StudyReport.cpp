#include "vesica/pipelines/StudyReport.h"

#include <fstream>
#include <set>

namespace fs = std::filesystem;

namespace vesica::pipelines {

StudyReport StudyReport::collect(const Plan& plan) {
  StudyReport report;
  for (const auto& s : plan.stages) {
    if (s.tool != "simulate") continue;
    StudyRow row;
    row.variant = s.variant;
    row.parameters = s.params;
    row.simulation = plan.in_workdir(s.output);
    std::ifstream in(row.simulation / "summary.json");
    if (in) row.summary = nlohmann::json::parse(in, nullptr, false);
    if (row.summary.is_discarded()) row.summary = nullptr;
    if (fs::exists(row.simulation / "history.csv"))
      row.history_csv = row.simulation / "history.csv";
    report.rows_.push_back(row);
  }
  return report;
}

std::string StudyReport::to_csv() const {
  std::set<std::string> keys;
  for (const auto& r : rows_)
    if (r.summary.is_object())
      for (const auto& [k, v] : r.summary.items())
        if (v.is_number()) keys.insert(k);
  std::string csv = "variant";
  for (const auto& k : keys) csv += "," + k;
  csv += "\n";
  for (const auto& r : rows_) {
    csv += r.variant;
    for (const auto& k : keys) {
      csv += ",";
      if (r.summary.is_object() && r.summary.contains(k) && r.summary[k].is_number())
        csv += r.summary[k].dump();
    }
    csv += "\n";
  }
  return csv;
}

}  // namespace vesica::pipelines
