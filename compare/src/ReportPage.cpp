#include "vesica/compare/ReportPage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "vesica/compare/ModelComparison.h"
#include "vesica/compare/SvgPlot.h"

namespace vesica::compare {
namespace {

const char* kMeasured = "#1f77b4";
const char* kFlagged = "#ff7f0e";
const char* kSimulated = "#d62728";
const char* kFitted = "#2ca02c";

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string cell(const nlohmann::json& v) {
  if (v.is_number()) return fmt(v.get<double>());
  if (v.is_string()) return xml_escape(v.get<std::string>());
  return "&ndash;";
}

struct Row {
  const char* key;
  const char* label;
};
const Row kParameterRows[] = {
    {"capacity_ml", "Cystometric capacity (ml)"},
    {"volume_start_ml", "Volume at start of filling (ml)"},
    {"pdet_start_cmh2o", "Pdet at start of filling (cmH2O)"},
    {"pdet_capacity_cmh2o", "Pdet at capacity (cmH2O)"},
    {"compliance_ml_per_cmh2o", "Compliance (ml/cmH2O)"},
    {"first_desire_ml", "First desire (ml)"},
    {"normal_desire_ml", "Normal desire (ml)"},
    {"strong_desire_ml", "Strong desire (ml)"},
    {"qmax_ml_s", "Qmax (ml/s)"},
    {"qave_ml_s", "Qave (ml/s)"},
    {"flow_time_s", "Flow time (s)"},
    {"voiding_time_s", "Voiding time (s)"},
    {"time_to_qmax_s", "Time to Qmax (s)"},
    {"voided_ml", "Voided volume (ml)"},
    {"pvr_ml", "Post-void residual (ml)"},
    {"voiding_efficiency", "Voiding efficiency (-)"},
    {"pdet_qmax_cmh2o", "PdetQmax (cmH2O)"},
    {"pdet_opening_cmh2o", "Pdet opening (cmH2O)"},
    {"pdet_max_voiding_cmh2o", "Pdet max, voiding (cmH2O)"},
    {"pdet_closing_cmh2o", "Pdet closing (cmH2O)"},
    {"booi", "BOOI = PdetQmax - 2 Qmax"},
    {"booi_class", "BOOI class"},
    {"bci", "BCI = PdetQmax + 5 Qmax"},
    {"bci_class", "BCI class"},
};

std::string parameter_table(const ReportInputs& in) {
  const nlohmann::json m = in.measured ? to_json(in.measured->ics) : nlohmann::json::object();
  const nlohmann::json s = in.simulated ? to_json(in.simulated->ics) : nlohmann::json::object();
  std::ostringstream o;
  o << "<table class=\"params\"><tr><th>Parameter</th><th>Measured</th><th>Simulated</th>"
    << "<th>Simulated &minus; measured</th></tr>\n";
  for (const auto& row : kParameterRows) {
    const auto mv = m.value(row.key, nlohmann::json());
    const auto sv = s.value(row.key, nlohmann::json());
    nlohmann::json d;
    if (mv.is_number() && sv.is_number()) d = sv.get<double>() - mv.get<double>();
    o << "<tr><td>" << xml_escape(row.label) << "</td><td>" << cell(mv) << "</td><td>" << cell(sv)
      << "</td><td>" << cell(d) << "</td></tr>\n";
  }
  o << "</table>\n";
  return o.str();
}

std::string figure(const SvgPlot& plot, const std::string& caption) {
  if (plot.empty()) return "<p class=\"missing\">" + xml_escape(caption) + ": no data.</p>\n";
  return "<figure>" + plot.render() + "<figcaption>" + xml_escape(caption) +
         "</figcaption></figure>\n";
}

Curve flagged_points(const RecordingAnalysis& a) {
  Curve c;
  for (const auto& f : a.flags)
    if (f.row <= a.ics.capacity_row && a.recording.has_pdet()) {
      c.x.push_back(a.recording.bladder_volume_ml(f.row));
      c.y.push_back(a.recording.pdet_cmh2o(f.row));
    }
  return c;
}

std::string filling_plot(const ReportInputs& in) {
  SvgPlot plot("Filling: detrusor pressure against volume", "bladder volume (ml)", "Pdet (cmH2O)");
  plot.id("plot-filling");
  plot.add_hband(6, 10, "normal end-filling Pdet");
  if (in.calibration)
    plot.add_vband(in.calibration->volume_lo_ml, in.calibration->volume_hi_ml, "fitted volumes",
                   "#cccccc");
  if (in.measured) {
    plot.add_points("measured", in.measured->filling.x, in.measured->filling.y, kMeasured);
    const Curve f = flagged_points(*in.measured);
    if (!f.x.empty()) plot.add_points("measured, flagged", f.x, f.y, kFlagged);
  }
  if (in.simulated)
    plot.add_line("simulated", in.simulated->filling.x, in.simulated->filling.y, kSimulated);
  if (in.calibration)
    plot.add(SvgPlot::Series{"fitted model", in.calibration->fitted_filling.x,
                             in.calibration->fitted_filling.y, SvgPlot::Style::Line, kFitted, 2.5,
                             3.5, true});
  return figure(plot, "Pdet(V) during filling; flagged rows are left out of every fit.");
}

std::string volume_plot(const ReportInputs& in) {
  SvgPlot plot("Volume against time", "time (s)", "volume (ml)");
  plot.id("plot-volume");
  auto add = [&](const RecordingAnalysis& a, const std::string& name, const char* color) {
    const auto& r = a.recording;
    std::vector<double> v(r.rows());
    for (std::size_t i = 0; i < r.rows(); ++i) v[i] = r.bladder_volume_ml(i);
    plot.add(SvgPlot::Series{name + " bladder volume", r.time_s, v, SvgPlot::Style::LinePoints,
                             color, 2, r.rows() > 200 ? 0.0 : 2.5});
    if (r.has_flow() || !r.voided_ml.empty())
      plot.add(SvgPlot::Series{name + " voided", r.time_s, r.voided_or_integrated_ml(),
                               SvgPlot::Style::Line, color, 2, 0, true});
  };
  if (in.measured) add(*in.measured, "measured", kMeasured);
  if (in.simulated) add(*in.simulated, "simulated", kSimulated);
  return figure(plot, "Bladder volume (solid) and voided volume (dashed).");
}

std::string flow_plot(const ReportInputs& in) {
  SvgPlot plot("Flow during voiding", "time since onset of flow (s)", "flow (ml/s)");
  plot.id("plot-flow");
  if (in.measured) {
    const auto c = voiding_curves(in.measured->recording, in.measured->ics);
    if (!c.flow_ml_s.x.empty())
      plot.add(SvgPlot::Series{"measured", c.flow_ml_s.x, c.flow_ml_s.y, SvgPlot::Style::LinePoints,
                               kMeasured});
  }
  if (in.simulated) {
    const auto c = voiding_curves(in.simulated->recording, in.simulated->ics);
    if (!c.flow_ml_s.x.empty())
      plot.add_line("simulated", c.flow_ml_s.x, c.flow_ml_s.y, kSimulated);
  }
  return figure(plot, "Uroflow Q(t) from the onset of measurable flow.");
}

// Pdet against flow during voiding, with the ICS nomogram lines: BOOI 20 and 40
// (Pdet = BOOI + 2 Q) and BCI 100 and 150 (Pdet = BCI - 5 Q).
std::string pressure_flow_plot(const ReportInputs& in) {
  SvgPlot plot("Pressure-flow", "flow Q (ml/s)", "Pdet (cmH2O)");
  plot.id("plot-pressure-flow").x_range(0, 30).y_range(0, 160);
  auto add = [&](const RecordingAnalysis& a, const std::string& name, const char* color) {
    const auto& r = a.recording;
    if (!r.has_flow() || !r.has_pdet()) return;
    Curve c;
    for (std::size_t i = 0; i < r.rows(); ++i)
      if (r.flow_ml_s[i] > 0 && !a.flagged[i]) {
        c.x.push_back(r.flow_ml_s[i]);
        c.y.push_back(r.pdet_cmh2o(i));
      }
    if (c.x.empty()) return;
    plot.add(SvgPlot::Series{name + " voiding", c.x, c.y,
                             r.rows() > 200 ? SvgPlot::Style::Line : SvgPlot::Style::Points, color,
                             1.5, 3});
    if (a.ics.qmax_ml_s && a.ics.pdet_qmax_cmh2o)
      plot.add(SvgPlot::Series{name + " Qmax, PdetQmax",
                               {*a.ics.qmax_ml_s},
                               {*a.ics.pdet_qmax_cmh2o},
                               SvgPlot::Style::Points,
                               color,
                               2,
                               7});
  };
  if (in.measured) add(*in.measured, "measured", kMeasured);
  if (in.simulated) add(*in.simulated, "simulated", kSimulated);
  plot.add_sloped_line(40, 2, "BOOI 40 (obstructed above)", "#8b0000");
  plot.add_sloped_line(20, 2, "BOOI 20 (unobstructed below)", "#e9967a");
  plot.add_sloped_line(150, -5, "BCI 150 (strong above)", "#006400");
  plot.add_sloped_line(100, -5, "BCI 100 (weak below)", "#66cdaa");
  return figure(plot, "Pressure-flow plot with the BOOI and BCI lines.");
}

std::string flags_section(const RecordingAnalysis* a, const std::string& name) {
  if (!a) return {};
  std::ostringstream o;
  o << "<h3>" << xml_escape(name) << " (" << xml_escape(a->recording.source) << ")</h3>\n";
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

std::string calibration_section(const CalibrationResult* c) {
  if (!c) return "<p>No calibration was requested.</p>\n";
  std::ostringstream o;
  o << "<table class=\"calibration\"><tr><th>Parameter</th><th>Fitted</th><th>95 % CI</th>"
    << "<th>Start</th><th>Bounds</th></tr>\n";
  for (const auto& p : c->parameters)
    o << "<tr><td>" << xml_escape(p.name) << " (" << xml_escape(p.unit) << ")</td><td>"
      << fmt(p.value) << "</td><td>" << fmt(p.ci_low) << " &ndash; " << fmt(p.ci_high)
      << "</td><td>" << fmt(p.initial) << "</td><td>" << fmt(p.lower) << " &ndash; " << fmt(p.upper)
      << "</td></tr>\n";
  o << "</table>\n<p>Fit over " << fmt(c->volume_lo_ml) << "&ndash;" << fmt(c->volume_hi_ml)
    << " ml: RMSE " << fmt(c->rmse_cmh2o) << " cmH2O, maximum error " << fmt(c->max_abs_error_cmh2o)
    << " cmH2O; " << c->simulations << " simulations, " << c->iterations << " iterations, "
    << fmt(c->seconds) << " s; " << xml_escape(c->status) << ".</p>\n";
  return o.str();
}

std::string wall_stress_section(const ReportInputs& in) {
  if (!in.wall_stress) return "<p>No simulation mesh was given (--mesh), so no picture.</p>\n";
  const auto& w = *in.wall_stress;
  if (w.png_base64.empty()) return "<p class=\"missing\">" + xml_escape(w.message) + "</p>\n";
  return "<figure><img id=\"wall-stress\" alt=\"wall stress at capacity\" "
         "src=\"data:image/png;base64," +
         w.png_base64 + "\"/><figcaption>" + xml_escape(w.message) + "</figcaption></figure>\n";
}

std::string comparison_section(const nlohmann::json& c) {
  if (c.is_null()) return "<p>Only one recording was given; nothing to compare.</p>\n";
  std::ostringstream o;
  o << "<table class=\"comparison\"><tr><th>Curve</th><th>Range</th><th>RMSE</th>"
    << "<th>Max error</th></tr>\n";
  auto row = [&](const char* key, const char* name, const char* unit, const char* axis) {
    const auto& d = c[key];
    const std::string u = unit;
    o << "<tr><td>" << name << "</td><td>" << cell(d["range_lo"]) << "&ndash;"
      << cell(d["range_hi"]) << ' ' << axis << "</td><td>" << cell(d["rmse_" + u]) << "</td><td>"
      << cell(d["max_abs_error_" + u]) << "</td></tr>\n";
  };
  row("filling_pdet", "Pdet(V) (cmH2O)", "cmh2o", "ml");
  row("voiding_voided_volume", "Voided V(t) (ml)", "ml", "s");
  row("voiding_flow", "Flow Q(t) (ml/s)", "ml_s", "s");
  return o.str() + "</table>\n";
}

// Reports script errors into the page (for the browser test) and records which plots
// rendered with visible content.
const char* kCheckScript = R"(<script>
window.onerror = function (msg) {
  var e = document.getElementById('js-errors');
  e.textContent += 'error: ' + msg + '\n';
};
window.addEventListener('load', function () {
  var plots = document.querySelectorAll('svg.plot'), drawn = 0;
  plots.forEach(function (svg) {
    var marks = svg.querySelectorAll('path.series, circle.series');
    var box = svg.getBoundingClientRect();
    if (marks.length > 0 && box.width > 0 && box.height > 0) drawn++;
  });
  document.getElementById('render-check').textContent =
      'plots=' + plots.length + ' drawn=' + drawn;
});
</script>
)";

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 2em; color: #222; max-width: 1100px; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; }
th, td { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
th:first-child, td:first-child { text-align: left; }
figure { display: inline-block; margin: 0.5em; }
figcaption { font-size: 0.9em; color: #555; }
.missing { color: #8b0000; }
#wall-stress { max-width: 800px; border: 1px solid #ccc; }
</style>
)";

}  // namespace

std::string report_html(const ReportInputs& in) {
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<title>vesica: urodynamics, model against measurement</title>\n"
    << kStyle << kCheckScript << "</head><body>\n";
  o << "<h1>Urodynamics: model against measurement</h1>\n<p>";
  if (in.measured) o << "Measured: " << xml_escape(in.measured->recording.source) << ". ";
  if (in.simulated) o << "Simulated: " << xml_escape(in.simulated->recording.source) << ". ";
  o << "Definitions: docs/compare.md (ICS terms, docs/physics.md &sect;7).</p>\n";
  o << "<h2>Plots</h2>\n"
    << filling_plot(in) << volume_plot(in) << flow_plot(in) << pressure_flow_plot(in);
  o << "<h2>Parameters</h2>\n" << parameter_table(in);
  o << "<h2>Model against measurement</h2>\n" << comparison_section(in.comparison);
  o << "<h2>Calibration</h2>\n" << calibration_section(in.calibration);
  o << "<h2>Wall stress at capacity</h2>\n" << wall_stress_section(in);
  o << "<h2>Flagged artefacts</h2>\n"
    << flags_section(in.measured, "Measured") << flags_section(in.simulated, "Simulated");
  o << "<pre id=\"js-errors\"></pre><p id=\"render-check\"></p>\n</body></html>\n";
  return o.str();
}

}  // namespace vesica::compare
