// The report's header: what was recorded (file, sex, age, fill rate) and what was
// simulated (every model setting a reader needs to judge the curves), vesica's version and
// the date.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/ReportParts.h"
#include "vesica/compare/html/SvgPlot.h"
#include "vesica/core/StageRecord.h"

namespace vesica::compare::report {
namespace {

namespace fs = std::filesystem;

std::string row(const std::string& name, const std::string& value_html) {
  return "<tr><th>" + xml_escape(name) + "</th><td>" + value_html + "</td></tr>\n";
}

// Material parameter names as a reader writes them.
std::string parameter_name(const std::string& key) {
  if (key == "mu") return "&mu;";
  if (key == "K_per_mu") return "K/&mu;";
  if (key.rfind("beta", 0) == 0) return "&beta;" + key.substr(4);
  if (key.rfind("tau", 0) == 0) return "&tau;" + key.substr(3);
  return xml_escape(key);
}

std::string material(const SimulationSettings& s) {
  std::string text = s.material == "neo-hookean" ? "neo-Hookean" : xml_escape(s.material);
  for (std::size_t i = 0; i < s.material_parameters.size(); ++i)
    text += (i ? ", " : ": ") + parameter_name(s.material_parameters[i].first) + " = " +
            xml_escape(s.material_parameters[i].second);
  return text;
}

std::string recording_card(const ReportInputs& in) {
  const RecordingAnalysis& m = *in.measured;
  const PatientFacts& p = in.patient;
  std::ostringstream o;
  o << "<section class=\"card\"><h2>Recording</h2><table class=\"facts\">\n";
  o << row("File", xml_escape(fs::path(m.recording.source).filename().string()));
  o << row("Sex", std::string(sex_name(p.sex)) +
                      (p.sex_source.empty() ? "" : " (" + xml_escape(p.sex_source) + ")"));
  o << row("Age", p.age_years ? number(*p.age_years, 3) + " years" : "not stated");
  // The rate the parameters and the calibration use (IcsParameters: --fill-rate-ml-min, else
  // the slope of the bladder volume over filling).
  std::string rate = m.ics.fill_rate_ml_min ? number(*m.ics.fill_rate_ml_min, 2) + " ml/min"
                                            : "not known (no time column)";
  if (p.stated_fill_rate_ml_min)
    rate += "; the recording states " + number(*p.stated_fill_rate_ml_min, 3) + " ml/min";
  o << row("Fill rate", rate);
  o << row("Rows", std::to_string(m.recording.rows()) + " (" + std::to_string(m.flags.size()) +
                       " flagged as artefacts, listed at the end)");
  o << "</table></section>\n";
  return o.str();
}

std::string outlet(const SimulationSettings& s) {
  if (!s.p_open_cmh2o) return "not recorded";
  return "opens at " + number(*s.p_open_cmh2o) +
         " cmH2O; above it P &minus; p<sub>open</sub> = " + "R1 Q + R2 Q&sup2; with R1 = " +
         (s.r1_cmh2o_s_per_ml ? number(*s.r1_cmh2o_s_per_ml) : "?") + " cmH2O&middot;s/ml, R2 = " +
         (s.r2_cmh2o_s2_per_ml2 ? number(*s.r2_cmh2o_s2_per_ml2) : "?") +
         " cmH2O&middot;s&sup2;/ml&sup2;";
}

std::string filling(const SimulationSettings& s) {
  if (!s.start_ml || !s.capacity_ml) return "not recorded";
  std::string text = number(*s.start_ml) + " &rarr; " + number(*s.capacity_ml) + " ml";
  if (s.fill_rate_ml_min) text += " at " + number(*s.fill_rate_ml_min) + " ml/min";
  if (s.residual_ml) text += " (stress-free wall at " + number(*s.residual_ml) + " ml)";
  return text;
}

std::string mesh(const SimulationSettings& s) {
  if (!s.triangles) return "not recorded";
  std::string text = std::to_string(*s.triangles) + " wall triangles";
  if (s.nodes) text += ", " + std::to_string(*s.nodes) + " nodes";
  if (s.mean_edge_mm) text += ", mean edge " + number(*s.mean_edge_mm, 2) + " mm";
  return text;
}

std::string model_card(const ReportInputs& in) {
  std::ostringstream o;
  o << "<section class=\"card\"><h2>Model</h2><table class=\"facts\">\n";
  o << row("Simulation", xml_escape(in.simulated->recording.source));
  if (!in.settings || in.settings->manifest.empty()) {
    o << row("Settings",
             "<span class=\"missing\">no manifest of vesica-simulate lists this "
             "history.csv: the settings are unknown</span>");
  }
  if (in.settings) {
    const SimulationSettings& s = *in.settings;
    if (!s.material.empty()) o << row("Wall material", material(s));
    o << row("Wall thickness", s.thickness_mm ? number(*s.thickness_mm) + " mm (" +
                                                    xml_escape(s.thickness_source) + ")"
                                              : "not recorded");
    o << row("Filling", filling(s));
    o << row("Voiding driven by", xml_escape(s.voiding_drive()));
    o << row("Outlet", outlet(s));
    o << row("Mesh", mesh(s));
    if (s.level)
      o << row("Urine model",
               *s.level == 2 ? "level 2: Navier&ndash;Stokes" : "level 1: hydrostatic volume");
    if (s.voiding_tail_from_ml)
      o << row("Tail of voiding",
               "from " + number(*s.voiding_tail_from_ml) +
                   " ml on, the wall's sphere-equivalent (level 0): the wall could not take a "
                   "voiding step there (docs/simulate.md)");
    if (!s.version.empty())
      o << row("Simulated by",
               "vesica " + xml_escape(s.version) +
                   (s.finished_utc.empty() ? "" : ", " + xml_escape(s.finished_utc)));
  }
  o << "</table></section>\n";
  return o.str();
}

}  // namespace

std::string number(double v, int significant) {
  if (!std::isfinite(v)) return "&ndash;";
  char buf[32];
  // whole numbers, and numbers beyond the precision, print in full (349 and 1234, not
  // 3.49e+02 and 1.23e+03)
  const bool whole = std::abs(v) >= 1 && std::abs(v) < 1e6 && std::abs(v - std::round(v)) < 1e-9;
  if (whole || std::abs(v) >= std::pow(10.0, significant))
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.*g", significant, std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

std::string number(const nlohmann::json& v, int significant) {
  if (v.is_number()) return number(v.get<double>(), significant);
  if (v.is_string() && !v.get<std::string>().empty()) return xml_escape(v.get<std::string>());
  return "&ndash;";
}

bool simulated_void_is_straining(const ReportInputs& in) {
  if (!in.simulated) return false;
  if (in.settings && !in.settings->manifest.empty()) return in.settings->straining();
  // Without settings: straining shows as Pabd rising while the bladder empties.
  const Recording& r = in.simulated->recording;
  const std::size_t c = in.simulated->ics.capacity_row;
  if (r.pabd_cmh2o.empty() || c + 1 >= r.rows()) return false;
  for (std::size_t i = c + 1; i < r.rows(); ++i)
    if (r.pabd_cmh2o[i] > r.pabd_cmh2o[c] + 2.0) return true;
  return false;
}

std::string simulated_voiding_label(const ReportInputs& in) {
  const bool straining = simulated_void_is_straining(in);
  const bool detrusor = in.settings && in.settings->detrusor();
  if (straining && detrusor) return "voiding by detrusor contraction and straining";
  if (straining) return "voiding by abdominal straining";
  if (detrusor) return "voiding by detrusor contraction";
  return "voiding";
}

std::string header_section(const ReportInputs& in) {
  std::ostringstream o;
  o << "<div class=\"cards\">\n";
  if (in.measured) o << recording_card(in);
  if (in.simulated) o << model_card(in);
  o << "</div>\n<p class=\"small\">Report by vesica " << xml_escape(version()) << ", "
    << xml_escape(in.generated_utc)
    << ". Units: volume ml, pressure cmH2O, flow ml/s, time s, stress kPa.</p>\n";
  return o.str();
}

}  // namespace vesica::compare::report
