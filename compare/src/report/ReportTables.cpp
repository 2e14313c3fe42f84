// The report's tables: ICS parameters measured against simulated, and the pressure-flow
// criteria of the patient's sex with their normal classes and published references.
#include <sstream>

#include "report/ReportParts.h"
#include "vesica/compare/html/SvgPlot.h"

namespace vesica::compare::report {
namespace {

struct Row {
  const char* key;
  const char* label;
  bool voiding_pressure;  // differs in kind when the simulated void is a strain
};
const Row kRows[] = {
    {"capacity_ml", "Cystometric capacity (ml)", false},
    {"volume_start_ml", "Volume at start of filling (ml)", false},
    {"pdet_start_cmh2o", "Pdet at start of filling (cmH2O)", false},
    {"pdet_capacity_cmh2o", "Pdet at capacity (cmH2O)", false},
    {"compliance_ml_per_cmh2o", "Compliance (ml/cmH2O)", false},
    {"first_desire_ml", "First desire (ml)", false},
    {"normal_desire_ml", "Normal desire (ml)", false},
    {"strong_desire_ml", "Strong desire (ml)", false},
    {"qmax_ml_s", "Qmax (ml/s)", false},
    {"qave_ml_s", "Qave (ml/s)", false},
    {"flow_time_s", "Flow time (s)", false},
    {"voiding_time_s", "Voiding time (s)", false},
    {"time_to_qmax_s", "Time to Qmax (s)", false},
    {"voided_ml", "Voided volume (ml)", false},
    {"pvr_ml", "Post-void residual (ml)", false},
    {"voiding_efficiency", "Voiding efficiency (-)", false},
    {"pdet_qmax_cmh2o", "PdetQmax (cmH2O)", true},
    {"pdet_opening_cmh2o", "Pdet opening (cmH2O)", true},
    {"pdet_max_voiding_cmh2o", "Pdet max, voiding (cmH2O)", true},
    {"pdet_closing_cmh2o", "Pdet closing (cmH2O)", true},
};

std::string criteria_rows(const std::vector<Criterion>& m, const std::vector<Criterion>& s) {
  std::ostringstream o;
  const std::size_t n = std::max(m.size(), s.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Criterion& c = i < m.size() ? m[i] : s[i];
    auto cells = [&](const std::vector<Criterion>& list) {
      if (i >= list.size()) return std::string("<td>&ndash;</td><td></td>");
      const Criterion& x = list[i];
      return "<td>" + (x.value ? number(*x.value) : std::string("&ndash;")) +
             "</td><td class=\"class\">" + xml_escape(x.verdict) + "</td>";
    };
    o << "<tr id=\"criterion-" << c.key << "\"><td>" << xml_escape(c.name) << "</td>" << cells(m)
      << cells(s) << "<td class=\"class\">" << xml_escape(c.normal) << "</td></tr>\n";
  }
  return o.str();
}

}  // namespace

std::string parameter_section(const ReportInputs& in) {
  const nlohmann::json m = in.measured ? to_json(in.measured->ics) : nlohmann::json::object();
  const nlohmann::json s = in.simulated ? to_json(in.simulated->ics) : nlohmann::json::object();
  const bool strain = simulated_void_is_straining(in);
  std::ostringstream o;
  o << "<table class=\"params\" id=\"parameters\"><tr><th>Parameter</th><th>Measured</th>"
    << "<th>Simulated</th><th>Simulated &minus; measured</th></tr>\n";
  for (const Row& row : kRows) {
    const auto mv = m.value(row.key, nlohmann::json());
    const auto sv = s.value(row.key, nlohmann::json());
    if (!mv.is_number() && !sv.is_number()) continue;
    nlohmann::json d;
    if (mv.is_number() && sv.is_number()) d = sv.get<double>() - mv.get<double>();
    const std::string mark = row.voiding_pressure && strain && sv.is_number() ? " &dagger;" : "";
    o << "<tr><td>" << xml_escape(row.label) << "</td><td>" << number(mv) << "</td><td>"
      << number(sv) << mark << "</td><td>" << number(d) << "</td></tr>\n";
  }
  o << "</table>\n";
  if (strain)
    o << "<p class=\"note\">&dagger; The simulated void is driven by abdominal straining: the "
         "bladder is squeezed from outside while the detrusor stays passive, so its voiding "
         "pressures are not a detrusor contraction's and differ from the measured ones in kind, "
         "not only in value.</p>\n";
  // A reference range is shown only with its published source (the criteria table below);
  // no source was found for the filling ranges once shown here, so none is given.
  o << "<p class=\"note\">Definitions: docs/compare.md (ICS terms). Reference ranges are "
       "given only where a published source is named: the pressure-flow criteria below.</p>\n";
  return o.str();
}

std::string criteria_section(const ReportInputs& in) {
  const Sex sex = in.patient.sex;
  const auto m = in.measured ? voiding_criteria(in.measured->ics, sex) : std::vector<Criterion>{};
  const auto s = in.simulated ? voiding_criteria(in.simulated->ics, sex) : std::vector<Criterion>{};
  std::ostringstream o;
  if (!m.empty() || !s.empty()) {
    o << "<table class=\"criteria\" id=\"criteria\"><tr><th>Criterion (" << sex_name(sex)
      << ")</th><th>Measured</th><th class=\"class\">Class</th><th>Simulated</th><th "
         "class=\"class\">"
      << "Class</th><th class=\"class\">Normal</th></tr>\n"
      << criteria_rows(m, s) << "</table>\n";
  }
  o << "<p class=\"caveat\">" << xml_escape(criteria_caveat(sex)) << "</p>\n";
  const auto& refs = m.empty() ? s : m;
  if (!refs.empty())
    o << "<p class=\"small\">Reference: " << xml_escape(refs.front().reference) << ".</p>\n";
  return o.str();
}

}  // namespace vesica::compare::report
