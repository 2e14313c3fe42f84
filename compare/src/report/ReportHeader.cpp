// The report's header: what was recorded (file, sex, age, fill rate) and what was
// simulated (every model setting a reader needs to judge the curves), vesica's version and
// the date.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "report/ReportParts.h"
#include "vesica/compare/html/SvgPlot.h"
#include "vesica/core/StageRecord.h"
#include "vesica/simulate/ModelCard.h"

namespace vesica::compare::report {
namespace {

namespace fs = std::filesystem;

std::string row(const std::string& name, const std::string& value_html) {
  return "<tr><th>" + xml_escape(name) + "</th><td>" + value_html + "</td></tr>\n";
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

std::string kpa(double pa) {
  return number(pa / 1e3) + " kPa";
}

std::string material(const simulate::MaterialCard& m) {
  std::string text = m.name + ": &mu; = " + kpa(m.mu_pa) + ", K = " + kpa(m.k_pa);
  if (m.fibers) text += ", k1 = " + kpa(m.k1_pa) + ", k2 = " + number(m.k2);
  for (std::size_t a = 0; a < m.branches.size(); ++a)
    text += ", &beta;" + std::to_string(a + 1) + " = " + number(m.branches[a].beta) + ", &tau;" +
            std::to_string(a + 1) + " = " + number(m.branches[a].tau_s) + " s";
  if (m.has_muscle())
    text +=
        "; detrusor muscle: contractility " + kpa(m.contractility_pa) + ", tone " + kpa(m.tone_pa);
  else
    text += "; no active muscle";
  return text;
}

std::string reference(const simulate::ModelCard& c) {
  const std::string how =
      c.wall.reference == simulate::ReferenceState::Scale
          ? "the image scaled to " + number(c.wall.residual_ml) + " ml"
          : "the image prestressed at " + number(c.protocol.image_pressure_cmh2o) + " cmH2O";
  return how + ": " + number(c.reference_volume_ml) + " ml";
}

std::string outlet(const simulate::ProtocolSettings& p) {
  return std::string(simulate::urethra_law_name(p)) + ": opens at " + number(p.p_open_cmh2o) +
         " cmH2O, closes at " + number(p.p_close_cmh2o) +
         " cmH2O; above closing P &minus; p<sub>close</sub> = R1 q + R2 q&sup2; with R1 = " +
         number(p.r1_cmh2o_s_per_ml) + " cmH2O&middot;s/ml, R2 = " + number(p.r2_cmh2o_s2_per_ml2) +
         " cmH2O&middot;s&sup2;/ml&sup2;" +
         (p.urethra_half_open_cmh2o > 0
              ? ", half open " + number(p.urethra_half_open_cmh2o) + " cmH2O above closing"
              : "");
}

std::string filling(const simulate::ProtocolSettings& p) {
  return number(p.start_ml) + " &rarr; " + number(p.capacity_ml) + " ml at " +
         number(p.fill_rate_ml_min) + " ml/min";
}

std::string voiding(const simulate::ModelCard& c) {
  std::string text = xml_escape(simulate::voiding_drive_text(c));
  if (c.protocol.void_after_fill && !c.protocol.voiding_pabd.empty())
    text += "; the abdominal pressure as recorded";
  return text;
}

std::string mesh(const simulate::ModelCard& c) {
  std::string text = std::to_string(c.mesh.triangles) + " wall triangles, " +
                     std::to_string(c.mesh.nodes) + " nodes, mean edge " +
                     number(c.mesh.mean_edge_mm, 2) + " mm";
  if (c.mesh.tetrahedra) text += ", " + std::to_string(c.mesh.tetrahedra) + " urine tetrahedra";
  if (!c.mesh.file.empty())
    text += " (" + xml_escape(std::filesystem::path(c.mesh.file).filename().string()) + ")";
  return text;
}

const char* level_name(int level) {
  if (level == 0) return "level 0: the wall's sphere-equivalent";
  if (level == 2) return "level 2: Navier&ndash;Stokes";
  return "level 1: hydrostatic volume";
}

void card_rows(const simulate::ModelCard& c, std::ostringstream& o) {
  o << row("Wall material", material(c.material));
  o << row("Wall thickness", number(c.mean_thickness_mm) + " mm on average");
  o << row("Stress-free wall", reference(c));
  o << row("Filling", filling(c.protocol));
  o << row("Voiding driven by", voiding(c));
  o << row("Urethra", outlet(c.protocol));
  o << row("Mesh", mesh(c));
  o << row("Urine model", level_name(c.numerics.level));
  for (const simulate::LevelHandOver& h : c.hand_overs)
    o << row("Hand-over", xml_escape(simulate::hand_over_text(h)) +
                              " (docs/simulate.md, &ldquo;Levels and their hand-overs&rdquo;)");
}

std::string model_card(const ReportInputs& in) {
  std::ostringstream o;
  o << "<section class=\"card\" id=\"model-card\"><h2>Model</h2><table class=\"facts\">\n";
  o << row("Simulation", xml_escape(in.simulated->recording.source));
  if (in.model && in.model->card)
    card_rows(*in.model->card, o);
  else
    o << row("Settings", "<span class=\"missing\">no model card: " +
                             xml_escape(in.model ? in.model->problem : "not read") +
                             "; the settings are unknown</span>");
  if (in.model && !in.model->version.empty())
    o << row("Simulated by", "vesica " + xml_escape(in.model->version));
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

// The card of the simulated recording, when it has one.
const simulate::ModelCard* simulated_card(const ReportInputs& in) {
  return in.simulated && in.model && in.model->card ? &*in.model->card : nullptr;
}

bool simulated_void_is_straining(const ReportInputs& in) {
  const simulate::ModelCard* c = simulated_card(in);
  return c && c->protocol.void_after_fill && c->protocol.drive == simulate::VoidingDrive::Straining;
}

std::string simulated_voiding_label(const ReportInputs& in) {
  const simulate::ModelCard* c = simulated_card(in);
  if (!c || !c->protocol.void_after_fill) return "voiding";
  if (c->protocol.drive == simulate::VoidingDrive::Straining)
    return "voiding by abdominal straining";
  return c->protocol.voiding_pabd.empty()
             ? "voiding by detrusor contraction"
             : "voiding by detrusor contraction, abdominal pressure as recorded";
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
