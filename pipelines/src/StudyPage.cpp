#include "vesica/pipelines/StudyPage.h"

#include <algorithm>
#include <sstream>

#include "vesica/compare/SvgPlot.h"

namespace vesica::pipelines {
namespace {

using compare::SvgPlot;
using compare::xml_escape;

// Artificial-bladder design targets (docs/physics.md §7).
constexpr double kDesignCapacityMl = 500.0;
constexpr double kDesignPdetLowCmh2o = 40.0;
constexpr double kDesignPdetHighCmh2o = 70.0;

std::string label_of(const StudyRow& row) {
  return row.variant.empty() ? "(shared)" : row.variant;
}

// Pdet against volume while filling, one line per variant. With `limits` the axes take in
// the design limits (capacity and pressure band); without, the pressure axis fits the data,
// because a compliant pouch stays far below the band and its curves would look flat.
std::string filling_plot(const StudyReport& report, bool limits) {
  SvgPlot plot(limits ? "Filling: Pdet against volume, design limits"
                      : "Filling: Pdet against volume, pressure axis fitted to the data",
               "volume (ml)", "Pdet (cmH2O)");
  plot.id(limits ? "plot-filling" : "plot-filling-detail");
  double v_max = kDesignCapacityMl * 1.1, p_max = limits ? kDesignPdetHighCmh2o * 1.1 : 0.0;
  for (const auto& row : report.rows()) {
    if (!row.curve || row.curve->size() == 0) continue;
    const CystometryCurve& c = *row.curve;
    const auto end = static_cast<long>(c.filling_end()) + 1;
    std::vector<double> v(c.volume_ml.begin(), c.volume_ml.begin() + end);
    std::vector<double> p(c.pdet_cmh2o.begin(), c.pdet_cmh2o.begin() + end);
    v_max = std::max(v_max, *std::max_element(v.begin(), v.end()) * 1.05);
    p_max = std::max(p_max, *std::max_element(p.begin(), p.end()) * 1.05);
    plot.add_line(label_of(row), v, p);
  }
  plot.x_range(0.0, v_max).y_range(0.0, p_max > 0.0 ? p_max : 1.0);
  if (limits)
    plot.add_hband(kDesignPdetLowCmh2o, kDesignPdetHighCmh2o, "design Pmax 40-70 cmH2O", "#f4c7c3");
  plot.add_vline(kDesignCapacityMl, "design capacity 500 ml");
  return plot.render();
}

// Flow against time from the start of voiding (the end of filling), one line per variant.
std::string flow_plot(const StudyReport& report) {
  SvgPlot plot("Voiding: flow against time", "time from end of filling (s)", "flow (ml/s)");
  plot.id("plot-flow");
  for (const auto& row : report.rows()) {
    if (!row.curve) continue;
    const CystometryCurve& c = *row.curve;
    const std::size_t end = c.filling_end();
    if (end + 1 >= c.size()) continue;  // never voided
    std::vector<double> t, q;
    for (std::size_t i = end; i < c.size(); ++i) {
      t.push_back(c.time_s[i] - c.time_s[end]);
      q.push_back(c.flow_ml_s[i]);
    }
    plot.add_line(label_of(row), t, q);
  }
  if (plot.empty()) return "<p class=\"missing\">No variant reached voiding.</p>\n";
  return plot.render();
}

std::string table(const StudyReport& report) {
  std::ostringstream o;
  const auto varied = report.varied_parameters();
  o << "<table id=\"study-table\">\n<tr><th>variant</th><th>status</th>";
  for (const auto& k : varied) o << "<th>" << xml_escape(k) << "</th>";
  for (const auto& [name, value] : StudyReport::metrics(StudyRow{}))
    o << "<th>" << xml_escape(name) << "</th>";
  o << "<th>failure</th></tr>\n";
  for (const auto& row : report.rows()) {
    o << "<tr><td>" << xml_escape(label_of(row)) << "</td><td class=\"" << row.status << "\">"
      << row.status << "</td>";
    for (const auto& k : varied) {
      std::string value;
      for (const auto& [rk, rv] : row.parameters)
        if (rk == k) value = rv;
      o << "<td>" << xml_escape(value) << "</td>";
    }
    for (const auto& [name, value] : StudyReport::metrics(row))
      o << "<td>" << xml_escape(value) << "</td>";
    o << "<td class=\"failure\">" << xml_escape(row.status == "ok" ? "" : row.failure)
      << "</td></tr>\n";
  }
  return o.str() + "</table>\n";
}

// Puts script errors on the page and records how many plots drew visible series, so a
// headless browser's DOM dump shows both.
const char* kCheckScript = R"(<script>
window.onerror = function (msg) {
  document.getElementById('js-errors').textContent += 'error: ' + msg + '\n';
};
window.addEventListener('load', function () {
  var plots = document.querySelectorAll('svg.plot'), drawn = 0;
  plots.forEach(function (svg) {
    var box = svg.getBoundingClientRect();
    if (svg.querySelector('.series') && box.width > 0 && box.height > 0) drawn++;
  });
  document.getElementById('render-check').textContent =
      'plots=' + plots.length + ' drawn=' + drawn;
});
</script>
)";

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 2em; color: #222; max-width: 1200px; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; font-size: 0.9em; }
th, td { border: 1px solid #ccc; padding: 3px 6px; text-align: right; }
th:first-child, td:first-child, td.failure { text-align: left; }
td.failed, td.failure, .missing { color: #8b0000; }
div.wide { overflow-x: auto; }
</style>
)";

}  // namespace

std::string study_html(const StudyReport& report, const std::string& study_name) {
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<link rel=\"icon\" href=\"data:,\">\n"  // no favicon request, so no console error
    << "<title>vesica study: " << xml_escape(study_name) << "</title>\n"
    << kStyle << kCheckScript << "</head><body>\n";
  o << "<h1>Study: " << xml_escape(study_name) << "</h1>\n"
    << "<p>One row per variant; the same numbers are in study.csv. Pdet at 300 and 500 ml is "
       "interpolated on the filling curve (empty when not reached); capacity at 40 cmH2O is "
       "the volume where filling Pdet first reaches 40 cmH2O; compliance is &Delta;V/&Delta;Pdet "
       "from the start to the end of filling (docs/physics.md &sect;7). Shaded: the artificial-"
       "bladder design limits (capacity about 500 ml, maximum pressure 40-70 cmH2O).</p>\n";
  o << "<div class=\"wide\">" << table(report) << "</div>\n"
    << filling_plot(report, true) << filling_plot(report, false) << flow_plot(report);
  o << "<pre id=\"js-errors\"></pre><p id=\"render-check\"></p>\n</body></html>\n";
  return o.str();
}

}  // namespace vesica::pipelines
