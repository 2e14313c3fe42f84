// The report's later sections: the wall stress at capacity (picture and its numbers), the
// curves' differences, the calibration, and the rows flagged as artefacts.
#include <sstream>

#include "report/ReportParts.h"
#include "vesica/compare/html/SvgPlot.h"

namespace vesica::compare::report {
namespace {

std::string stress_table(const WallStressPicture& picture) {
  const nlohmann::json facts = picture_facts(picture);
  const nlohmann::json& s = facts["summary"];
  std::ostringstream o;
  o << "<table class=\"facts\" id=\"wall-stress-numbers\">\n"
    << "<tr><th>95th percentile (by wall area)</th><td>" << number(s["p95_kpa"])
    << " kPa</td></tr>\n"
    << "<tr><th>Maximum</th><td>" << number(s["max_kpa"]) << " kPa, "
    << xml_escape(s.value("where", "")) << "</td></tr>\n"
    << "<tr><th>Frame</th><td>" << xml_escape(facts.value("frame", ""));
  if (s["volume_ml"].is_number()) o << ": V = " << number(s["volume_ml"]) << " ml";
  if (s["pdet_cmh2o"].is_number()) o << ", Pdet = " << number(s["pdet_cmh2o"]) << " cmH2O";
  if (s["time_s"].is_number()) o << ", t = " << number(s["time_s"]) << " s";
  o << "</td></tr>\n</table>\n";
  return o.str();
}

std::string comparison_table(const nlohmann::json* comparison) {
  if (!comparison) return "<p>Only one recording was given; nothing to compare.</p>\n";
  const nlohmann::json& c = *comparison;
  std::ostringstream o;
  o << "<table class=\"comparison\"><tr><th>Curve</th><th>Range</th><th>RMSE</th>"
    << "<th>Max error</th></tr>\n";
  auto row = [&](const char* key, const char* name, const char* unit, const char* axis) {
    const auto& d = c[key];
    const std::string u = unit;
    o << "<tr><td>" << name << "</td><td>" << number(d["range_lo"]) << "&ndash;"
      << number(d["range_hi"]) << ' ' << axis << "</td><td>" << number(d["rmse_" + u])
      << "</td><td>" << number(d["max_abs_error_" + u]) << "</td></tr>\n";
  };
  row("filling_pdet", "Pdet(V) (cmH2O)", "cmh2o", "ml");
  row("voiding_voided_volume", "Voided V(t) (ml)", "ml", "s");
  row("voiding_flow", "Flow Q(t) (ml/s)", "ml_s", "s");
  return o.str() + "</table>\n";
}

// Each fitted series beside what a constant and a straight line achieve on the same
// readings: a fit that does not beat the line has not explained the data.
std::string calibration_series(const CalibrationResult& c) {
  if (c.series.empty()) return {};
  std::ostringstream o;
  o << "<table class=\"calibration-series\"><tr><th>Series</th><th>Readings</th><th>RMSE</th>"
    << "<th>Max error</th><th>Constant baseline</th><th>Straight-line baseline</th>"
    << "<th>Beats the line</th></tr>\n";
  for (const auto& s : c.series)
    o << "<tr><td>" << xml_escape(s.name) << " (" << xml_escape(s.unit) << ")</td><td>" << s.points
      << "</td><td>" << number(s.rmse) << "</td><td>" << number(s.max_abs_error) << "</td><td>"
      << number(s.constant_rmse) << "</td><td>" << number(s.line_rmse) << "</td><td>"
      << (s.beats_line ? "yes" : "no") << "</td></tr>\n";
  return o.str() + "</table>\n";
}

std::string calibration_table(const CalibrationResult* c) {
  if (!c) return "<p>No calibration was requested.</p>\n";
  std::ostringstream o;
  o << "<table class=\"calibration\"><tr><th>Parameter</th><th>Fitted</th><th>95 % CI</th>"
    << "<th>Start</th><th>Bounds</th><th>Identified</th></tr>\n";
  for (const auto& p : c->parameters)
    o << "<tr><td>" << xml_escape(p.name) << " (" << xml_escape(p.unit) << ")</td><td>"
      << number(p.value) << "</td><td>" << number(p.ci_low) << " &ndash; " << number(p.ci_high)
      << "</td><td>" << number(p.initial) << "</td><td>" << number(p.lower) << " &ndash; "
      << number(p.upper) << "</td><td>" << (p.identifiable ? "yes" : "no")
      << (p.note.empty() ? "" : ": " + xml_escape(p.note)) << "</td></tr>\n";
  o << "</table>\n" << calibration_series(*c);
  o << "<p>Fit over " << number(c->volume_lo_ml) << "&ndash;" << number(c->volume_hi_ml)
    << " ml: RMSE " << number(c->rmse_cmh2o) << " cmH2O, maximum error "
    << number(c->max_abs_error_cmh2o) << " cmH2O; " << c->simulations << " simulations ("
    << c->failed_simulations << " failed), " << c->iterations << " iterations; "
    << xml_escape(c->status) << ".</p>\n";
  for (const auto& note : c->notes) o << "<p class=\"note\">" << xml_escape(note) << "</p>\n";
  if (c->fitted_card)
    o << "<p id=\"fitted-model\">The fitted model's card is <code>model.json</code> beside this "
         "page; <code>vesica-simulate MESH --model-card model.json</code> runs it again: "
      << xml_escape(c->fitted_card->material.name) << " ("
      << xml_escape(simulate::material_text(c->fitted_card->material))
      << "), voiding: " << xml_escape(simulate::voiding_drive_text(*c->fitted_card)) << ".</p>\n";
  return o.str();
}

std::string flags_table(const RecordingAnalysis* a) {
  if (!a) return {};
  std::ostringstream o;
  o << "<h3>Measured (" << xml_escape(a->recording.source) << ")</h3>\n";
  if (a->flags.empty()) return o.str() + "<p>No artefacts flagged.</p>\n";
  o << "<table class=\"flags\"><tr><th>Line</th><th>Event</th><th>Artefact</th>"
    << "<th>Why</th></tr>\n";
  // The first rows only: a recording of noise can flag every one of its rows.
  constexpr std::size_t kShownFlags = 200;
  for (std::size_t i = 0; i < a->flags.size() && i < kShownFlags; ++i) {
    const auto& f = a->flags[i];
    o << "<tr><td>" << f.line << "</td><td>" << xml_escape(f.event) << "</td><td>"
      << xml_escape(f.kind) << "</td><td>" << xml_escape(f.detail) << "</td></tr>\n";
  }
  if (a->flags.size() > kShownFlags)
    o << "<tr><td colspan=\"4\">... and " << a->flags.size() - kShownFlags
      << " more (metrics.json lists them all)</td></tr>\n";
  return o.str() + "</table>\n";
}

}  // namespace

std::string wall_stress_section(const ReportInputs& in) {
  if (!in.wall_stress)
    return "<p>No simulation frame was found (series.pvd beside the "
           "history, or --mesh), so no picture.</p>\n";
  const auto& w = *in.wall_stress;
  if (w.png.empty()) return "<p class=\"missing\">" + xml_escape(w.message) + "</p>\n";
  return "<div class=\"stress\"><figure><img id=\"wall-stress\" alt=\"wall stress at capacity, "
         "anterior view\" src=\"data:image/png;base64," +
         base64(w.png) + "\"/><figcaption>" + xml_escape(w.message) +
         ": each triangle coloured by its maximum principal Cauchy stress &sigma;1 (viridis, "
         "unshaded, from the 2nd to the 98th percentile of the wall's area; the lowest 2 % "
         "black, the highest 2 % pink); the outlet cap (held fixed in the model) grey and left "
         "out of the numbers.</figcaption></figure>\n" +
         stress_table(w) + "</div>\n";
}

std::string fluid_jet_section(const ReportInputs& in) {
  const FluidJetPicture& j = *in.fluid_jet;
  if (j.svg.empty()) return "<p class=\"missing\">" + xml_escape(j.message) + "</p>\n";
  return "<figure>" + j.svg + "<figcaption>" + xml_escape(j.message) +
         ": each section of a urine tetrahedron coloured by the mean speed of its corners "
         "(viridis, 0 to the frame's maximum).</figcaption></figure>\n";
}

std::string details_section(const ReportInputs& in) {
  std::ostringstream o;
  o << "<section class=\"together\"><h2>Model against measurement</h2>\n"
    << comparison_table(in.comparison) << "</section>\n";
  o << "<section class=\"together\"><h2>Calibration</h2>\n"
    << calibration_table(in.calibration) << "</section>\n";
  o << "<section class=\"together\"><h2>Rows flagged as artefacts</h2>\n"
    << flags_table(in.measured);
  if (in.simulated)
    o << "<p>The simulated recording has no catheters and no artefacts: its phases are "
         "labelled by what drives them (trace above).</p>\n";
  o << "</section>\n";
  return o.str();
}

}  // namespace vesica::compare::report
