#include "vesica/pipelines/StudyPage.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "vesica/compare/html/PageCheckScript.h"
#include "vesica/compare/html/SvgPlot.h"
#include "vesica/pipelines/PouchPicture.h"
#include "vesica/pipelines/StudyRanking.h"

namespace vesica::pipelines {
namespace {

using compare::SvgPlot;
using compare::xml_escape;

// Artificial-bladder design targets (docs/physics.md §7.4).
constexpr double kDesignCapacityMl = 500.0;
constexpr double kDesignPdetLowCmh2o = 40.0;
constexpr double kDesignPdetHighCmh2o = 70.0;

// Okabe-Ito colours (told apart by colour-blind readers; yellow left out on white) and
// dash patterns, so that eight or more curves stay distinguishable.
const char* kColours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                          "#e69f00", "#56b4e9", "#000000", "#999999"};
const char* kDashes[] = {"", "9 4", "2 3", "12 3 3 3"};

// Three significant digits; whole numbers from 1000 on in full.
std::string sig3(double v) {
  char buf[32];
  if (std::abs(v) >= 1000)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else
    std::snprintf(buf, sizeof buf, "%.3g", std::abs(v) < 1e-12 ? 0.0 : v);
  return buf;
}

std::string shown(const StudyValue& v) {
  return v.value ? (v.above ? "&gt;" : "") + sig3(*v.value) : "&ndash;";
}

// Line styles: colour by the distinct parameter with the most values, dash by the others.
struct Style {
  std::string colour, dash;
};
std::vector<Style> line_styles(const StudyReport& report) {
  const auto keys = report.distinct_parameters();
  std::string by_colour;
  std::size_t most = 0;
  for (const auto& k : keys) {
    std::set<std::string> values;
    for (const auto& r : report.rows()) values.insert(report.parameter(r, k));
    if (values.size() > most) most = values.size(), by_colour = k;
  }
  std::map<std::string, std::size_t> colour_of, dash_of;
  std::vector<Style> styles;
  for (const auto& r : report.rows()) {
    std::string rest;
    for (const auto& k : keys)
      if (k != by_colour) rest += report.parameter(r, k) + "|";
    const std::string c = by_colour.empty() ? r.variant : report.parameter(r, by_colour);
    const std::size_t ci = colour_of.emplace(c, colour_of.size()).first->second;
    const std::size_t di = dash_of.emplace(rest, dash_of.size()).first->second;
    styles.push_back({kColours[ci % 8], kDashes[(di + ci / 8) % 4]});
  }
  return styles;
}

void add_curve(SvgPlot& plot, const std::string& label, const Style& s, std::vector<double> x,
               std::vector<double> y) {
  SvgPlot::Series series{label, std::move(x), std::move(y), SvgPlot::Style::Line, s.colour, 2.0};
  series.dash = s.dash;
  plot.add(std::move(series));
}

// The filling part of a curve: volume and Pdet up to the first row of largest volume.
std::pair<std::vector<double>, std::vector<double>> filling_of(const CystometryCurve& c) {
  const auto end = static_cast<long>(c.filling_end()) + 1;
  return {{c.volume_ml.begin(), c.volume_ml.begin() + end},
          {c.pdet_cmh2o.begin(), c.pdet_cmh2o.begin() + end}};
}

// The band between the fillings of a row's uncertainty ends, in the row's colour: under
// the softer wall's curve (the lower Pdet where both filled) and over the stiffer one's.
// Where the stiffer wall stopped at the pressure limit and the softer filled on, the band
// reaches up to where the stiffer stopped: a wall between them holds that pressure somewhere
// between the two volumes. With two ends, the soft and the stiff wall bound every wall
// between them, as Pdet at a volume grows with each parameter.
void add_band(SvgPlot& plot, const StudyReport& report, const StudyRow& row, const Style& s) {
  std::vector<const StudyRow*> ends;
  for (const StudyRow* b : report.bounds_of(row))
    if (b->curve && b->curve->size() > 0) ends.push_back(b);
  if (ends.size() < 2) return;
  auto lower = filling_of(*ends.front()->curve);
  auto upper = filling_of(*ends.back()->curve);
  // The upper curve is the one with the higher Pdet at the largest volume both reached.
  const double common = std::min(lower.first.back(), upper.first.back());
  const auto pdet_at = [common](const std::pair<std::vector<double>, std::vector<double>>& c) {
    std::size_t k = 0;
    while (k + 1 < c.first.size() && c.first[k + 1] <= common) ++k;
    return c.second[k];
  };
  if (pdet_at(lower) > pdet_at(upper)) std::swap(lower, upper);
  auto [x, y] = lower;
  const double top = std::max(upper.second.back(), lower.second.back());
  if (lower.first.back() > upper.first.back()) {  // up to where the stiffer one stopped
    x.push_back(lower.first.back());
    y.push_back(top);
  }
  x.insert(x.end(), upper.first.rbegin(), upper.first.rend());
  y.insert(y.end(), upper.second.rbegin(), upper.second.rend());
  plot.add(SvgPlot::Series{"", std::move(x), std::move(y), SvgPlot::Style::Area, s.colour});
}

// Pdet against volume while filling, one line per variant. With `limits` the axes take in
// the design limits and the study's own; without, the pressure axis fits the data, because
// a compliant pouch stays far below the band and its curves would look flat.
std::string filling_plot(const StudyReport& report, bool limits) {
  SvgPlot plot(limits ? "Filling: Pdet against volume, with the limits"
                      : "Filling: Pdet against volume, axis fitted to the data",
               "volume (ml)", "Pdet (cmH2O)");
  plot.id(limits ? "plot-filling" : "plot-filling-detail").size(580, 340).legend_below();
  double v_max = kDesignCapacityMl * 1.1, p_max = limits ? kDesignPdetHighCmh2o * 1.1 : 0.0;
  const auto styles = line_styles(report);
  for (std::size_t i = 0; i < report.rows().size(); ++i) {
    const StudyRow& row = report.rows()[i];
    if (!row.curve || row.curve->size() == 0) continue;
    auto [v, p] = filling_of(*row.curve);
    v_max = std::max(v_max, *std::max_element(v.begin(), v.end()) * 1.05);
    p_max = std::max(p_max, *std::max_element(p.begin(), p.end()) * 1.05);
    add_band(plot, report, row, styles[i]);
    add_curve(plot, report.label(row), styles[i], v, p);
  }
  plot.x_range(0.0, v_max).y_range(0.0, p_max > 0.0 ? p_max : 1.0);
  if (limits) {
    plot.add_hband(kDesignPdetLowCmh2o, kDesignPdetHighCmh2o, "design Pmax 40-70 cmH2O", "#f4c7c3");
    for (const StudyLimit& l : report.limits())
      if (l.metric.rfind("pdet", 0) == 0 && l.max)
        plot.add_hline(*l.max, "limit: " + limit_text(l), "#8b0000");
  }
  plot.add_vline(kDesignCapacityMl, "design capacity 500 ml");
  return plot.render();
}

// Flow against time from the start of voiding (the end of filling), one line per variant.
std::string flow_plot(const StudyReport& report) {
  SvgPlot plot("Voiding: flow against time", "time from end of filling (s)", "flow (ml/s)");
  plot.id("plot-flow").size(580, 340).legend_below().y_floor(0);
  const auto styles = line_styles(report);
  for (std::size_t i = 0; i < report.rows().size(); ++i) {
    const StudyRow& row = report.rows()[i];
    if (!row.curve) continue;
    const CystometryCurve& c = *row.curve;
    const std::size_t end = c.filling_end();
    if (end + 1 >= c.size()) continue;  // never voided
    std::vector<double> t, q;
    for (std::size_t k = end; k < c.size(); ++k) {
      t.push_back(c.time_s[k] - c.time_s[end]);
      q.push_back(c.flow_ml_s[k]);
    }
    add_curve(plot, report.label(row), styles[i], t, q);
  }
  if (plot.empty()) return "<p class=\"missing\">No variant reached voiding.</p>\n";
  return plot.render();
}

// "surface.volume_ml" -> "volume_ml" over a small "surface".
std::string parameter_heading(const std::string& key) {
  const auto dot = key.find('.');
  if (dot == std::string::npos) return xml_escape(key);
  return xml_escape(key.substr(dot + 1)) + "<br><small>" + xml_escape(key.substr(0, dot)) +
         "</small>";
}

// Variant names break after their underscores.
std::string breakable(const std::string& name) {
  std::string out;
  for (char c : xml_escape(name)) out += c == '_' ? std::string("_<wbr>") : std::string(1, c);
  return out;
}

// The read-outs an interval is shown for: those of filling, which the uncertainty's runs
// make (they fill only).
bool has_interval(const std::string& key) {
  return key == "pdet_at_300ml_cmh2o" || key == "pdet_at_500ml_cmh2o" ||
         key == "compliance_ml_per_cmh2o" || key == "capacity_at_40cmh2o_ml";
}

// "<br><small>lo–hi</small>": the read-out at the ends of the uncertainty, lowest first.
std::string interval(const StudyReport& report, const StudyRow& row, const std::string& key) {
  if (!has_interval(key)) return "";
  std::vector<StudyValue> at_ends;
  for (const StudyRow* b : report.bounds_of(row))
    for (const auto& [k, v] : StudyReport::values(*b))
      if (k == key && v.value) at_ends.push_back(v);
  if (at_ends.size() < 2) return "";
  std::sort(at_ends.begin(), at_ends.end(),
            [](const StudyValue& a, const StudyValue& b) { return *a.value < *b.value; });
  return "<br><small class=\"interval\">" + shown(at_ends.front()) + "&ndash;" +
         shown(at_ends.back()) + "</small>";
}

// What the uncertainty's ends change, read off the first row that has them: "soft: mu_kpa
// 1, k1_kpa 0.06; stiff: ...".
std::string ends_text(const StudyReport& report) {
  for (const StudyRow& row : report.rows()) {
    const auto bounds = report.bounds_of(row);
    if (bounds.empty()) continue;
    std::string text;
    for (const StudyRow* b : bounds) {
      std::string changed;
      for (const auto& [k, v] : b->parameters) {
        if (report.parameter(row, k) == v || k.find("no_void") != std::string::npos) continue;
        changed += (changed.empty() ? "" : ", ") + k.substr(k.find('.') + 1) + " " + v;
      }
      text += (text.empty() ? "" : "; ") + b->bound + ": " + changed;
    }
    return text;
  }
  return "";
}

PictureScale picture_scale(const StudyReport& report) {
  PictureScale s;
  double extent = 0.0, stress = 0.0;
  for (const auto& r : report.rows()) {
    extent = std::max(extent, projection_extent_mm(r.capacity_stress));
    if (r.capacity_stress.is_object())
      stress = std::max(stress, r.capacity_stress["summary"].value("max_kpa", 0.0));
  }
  s.px_per_mm = extent > 0 ? (s.size_px - 8) / extent : 1.0;
  s.stress_max_kpa = stress > 0 ? stress : 1.0;
  return s;
}

std::string table(const StudyReport& report) {
  const auto keys = report.distinct_parameters();
  const PictureScale scale = picture_scale(report);
  std::ostringstream o;
  o << "<table id=\"study-table\">\n<tr><th>rank</th><th>variant</th><th>answer</th>";
  for (const auto& k : keys) o << "<th>" << parameter_heading(k) << "</th>";
  o << "<th>shape at capacity</th>";
  for (const StudyMetric& m : study_metrics())
    o << "<th>" << xml_escape(m.label) << "<br><small>" << xml_escape(m.unit) << "</small></th>";
  o << "<th>where the max is</th></tr>\n";
  int rank = 0;
  for (const std::size_t index : rank_by_capacity(report)) {
    const StudyRow& row = report.rows()[index];
    const std::string answer = row.status == "ok" ? report.answer(row) : row.status;
    o << "<tr><td class=\"rank\">" << ++rank << "</td><td class=\"variant\">"
      << breakable(report.label(row)) << "</td><td class=\"answer "
      << (answer == "not run" ? "not-run" : answer) << "\">"
      << (answer.empty() ? "&ndash;" : xml_escape(answer)) << "</td>";
    for (const auto& k : keys) o << "<td>" << xml_escape(report.parameter(row, k)) << "</td>";
    o << "<td class=\"picture\">" << pouch_picture(row.capacity_stress, scale) << "</td>";
    for (const auto& [key, value] : StudyReport::values(row))
      o << "<td>" << shown(value) << interval(report, row, key) << "</td>";
    const std::string where =
        row.capacity_stress.is_object() ? row.capacity_stress["summary"].value("where", "") : "";
    o << "<td class=\"where\">" << xml_escape(where) << "</td></tr>\n";
  }
  o << "</table>\n<p class=\"note\">Pictures: the wall at capacity seen from the front, each "
       "triangle coloured by its maximum principal stress on one scale for all variants "
    << stress_scale_bar(scale)
    << "; the outlet ringed in black, the largest stress crossed in red (it may lie on the far "
       "side); one mm scale for all, so sizes compare.</p>\n";
  return o.str();
}

// The question, the limits it is judged by, and the answer in one sentence.
std::string answer_section(const StudyReport& report) {
  std::ostringstream o;
  o << "<section class=\"answer\">\n";
  if (!report.question().empty())
    o << "<p class=\"question\"><b>Question:</b> " << xml_escape(report.question()) << "</p>\n";
  const std::string sentence = capacity_answer(report);
  if (!sentence.empty())
    o << "<p class=\"sentence\" id=\"answer-sentence\"><b>Answer:</b> " << xml_escape(sentence)
      << " The table is ranked by it.</p>\n";
  const std::string robust = robustness_answer(report);
  if (!robust.empty())
    o << "<p class=\"sentence\" id=\"robustness-sentence\"><b>Uncertainty:</b> "
      << xml_escape(robust) << " Each variant was also filled with the wall at the ends of its "
      << "documented ranges (" << xml_escape(ends_text(report))
      << "): the bands on the filling curves and the intervals under the read-outs.</p>\n";
  if (report.limits().empty()) {
    o << "<p>The study file sets no <code>limits:</code>, so no variant is judged pass or "
         "fail.</p>\n</section>\n";
    return o.str();
  }
  o << "<p><b>Limits</b> (study file): ";
  for (std::size_t i = 0; i < report.limits().size(); ++i)
    o << (i ? "; " : "") << xml_escape(limit_text(report.limits()[i]));
  std::vector<std::string> pass, fail, open;
  for (const auto& row : report.rows()) {
    const std::string a = report.answer(row);
    (a == "pass" ? pass : a == "fail" ? fail : open).push_back(report.label(row));
  }
  auto list = [](const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + xml_escape(n);
    return s;
  };
  o << ".</p>\n<p class=\"verdict\"><b>Against the limits:</b> " << pass.size() << " of "
    << report.rows().size() << " variants pass";
  if (!fail.empty()) o << "; fail: " << list(fail);
  if (!open.empty()) o << "; not answered (not reached or not run): " << list(open);
  o << ".</p>\n</section>\n";
  return o.str();
}

// Which model level ran (docs/physics.md §4.1, §11), from the parameters that ran: the
// sphere-equivalent (level 0) is exact for a sphere only, so a reader must know.
std::string level_note(const StudyReport& report) {
  std::set<std::string> levels;
  for (const auto& row : report.rows()) {
    const std::string given = report.parameter(row, "simulate.level");
    levels.insert(given.empty() ? "1" : given);
  }
  std::string list;
  for (const auto& l : levels) list += (list.empty() ? "" : ", ") + l;
  return "<p class=\"note\">Model level: " + xml_escape(list) +
         (levels.count("0") ? " (level 0 is the wall's sphere-equivalent: exact for a sphere, "
                              "blind to any other shape)"
                            : " (the 3-D membrane wall with hydrostatic urine: every shape as "
                              "built)") +
         ".</p>\n";
}

std::string notes(const StudyReport& report) {
  std::ostringstream o;
  o << level_note(report);
  std::vector<std::pair<std::string, std::string>> repeats;
  report.distinct_parameters(&repeats);
  if (!repeats.empty()) {
    o << "<p class=\"note\">Not shown, because each only repeats another column: ";
    for (std::size_t i = 0; i < repeats.size(); ++i)
      o << (i ? "; " : "") << xml_escape(repeats[i].first) << " (goes with "
        << xml_escape(repeats[i].second) << ")";
    o << ". All are in study.csv.</p>\n";
  }
  for (const auto& row : report.rows())
    if (row.status != "ok")
      o << "<p class=\"missing\">" << xml_escape(report.label(row)) << ": "
        << xml_escape(row.status) << (row.failure.empty() ? "" : ": " + xml_escape(row.failure))
        << "</p>\n";
  return o.str();
}

// How far the study table reaches, to check that it fits the window.
const char* kTableReach =
    R"(  var table = document.getElementById('study-table').getBoundingClientRect();
  document.body.dataset.tableRight = Math.ceil(table.right);
)";

const char* kStyle = R"(<style>
body { font-family: sans-serif; margin: 16px auto; padding: 0 16px; color: #222; }
h1 { font-size: 1.4em; margin: 0.2em 0; }
h2 { font-size: 1.15em; margin: 1.2em 0 0.4em; border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.5em 0; font-size: 12px; width: 100%; }
th, td { border: 1px solid #ccc; padding: 2px 4px; text-align: right; vertical-align: middle; }
th { font-weight: normal; background: #f4f4f4; }
th small, td small { color: #666; }
td.variant, td.where, th:first-child { text-align: left; }
td.variant { overflow-wrap: anywhere; min-width: 6em; }
td.picture { padding: 0; text-align: center; }
td.answer { font-weight: bold; text-align: center; }
td.pass { color: #006400; background: #e7f4e4; }
td.fail, td.failed { color: #8b0000; background: #fbe4e1; }
.answer .question { font-size: 1.1em; }
.verdict { font-size: 1.1em; }
.note, .small { font-size: 0.85em; color: #555; }
.note svg { vertical-align: middle; }
.missing { color: #8b0000; }
.plots { display: grid; grid-template-columns: repeat(auto-fit, minmax(480px, 1fr)); gap: 8px; }
svg.plot { display: block; }
</style>
)";

}  // namespace

std::string study_html(const StudyReport& report, const std::string& study_name) {
  std::ostringstream o;
  o << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
    << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
    << "<link rel=\"icon\" href=\"data:,\">\n"  // no favicon request, so no console error
    << "<title>vesica study: " << xml_escape(study_name) << "</title>\n"
    << kStyle << compare::page_check_script(kTableReach) << "</head><body>\n";
  o << "<h1>Study: " << xml_escape(study_name) << "</h1>\n" << answer_section(report);
  o << table(report) << notes(report);
  o << "<h2>Curves</h2>\n<div class=\"plots\">\n"
    << filling_plot(report, true) << filling_plot(report, false) << flow_plot(report) << "</div>\n";
  o << "<h2>How the numbers are computed</h2>\n"
    << "<p class=\"small\">One row per variant; every number, with more digits, is in "
       "study.csv. Pdet at 300 and 500 ml is interpolated on the filling curve (empty when "
       "not reached); the volume at 40 cmH2O is where filling Pdet first reaches 40 cmH2O "
       "(&gt;V: never, up to the largest volume V); compliance is &Delta;V/&Delta;Pdet from "
       "the start to the end of filling (docs/physics.md &sect;7.4). Wall stress: the "
       "maximum principal Cauchy stress of each triangle in the series frame at capacity "
       "(the first row of largest volume); the 95th percentile by wall area, and the "
       "maximum with where it sits; the outlet cap is left out. Shaded in the first plot: "
       "the artificial-bladder design limits (capacity about 500 ml, maximum pressure "
       "40-70 cmH2O).</p>\n";
  o << "<pre id=\"js-errors\" hidden></pre>\n</body></html>\n";
  return o.str();
}

}  // namespace vesica::pipelines
