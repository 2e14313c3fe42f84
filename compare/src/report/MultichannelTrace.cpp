#include "vesica/compare/report/MultichannelTrace.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "vesica/compare/html/SvgPlot.h"

namespace vesica::compare {
namespace {

constexpr double kLeft = 112, kRight = 16, kLegend = 24, kPhaseRow = 20, kEventRow = 30;
constexpr double kPanel = 76, kGap = 12, kAxis = 44;

std::string num(double v) {
  return svg_number(v);
}

}  // namespace

MultichannelTrace::MultichannelTrace(std::string id, std::string time_label, int width)
    : id_(std::move(id)), time_label_(std::move(time_label)), width_(width) {}

std::size_t MultichannelTrace::add_panel(std::string channel, std::string unit, double floor) {
  panels_.push_back({std::move(channel), std::move(unit), floor, {}});
  return panels_.size() - 1;
}

void MultichannelTrace::add_line(std::size_t panel, Line line) {
  if (line.t.size() > kMaxDrawnPoints) line.radius = 0.0;  // no dot per sample then
  thin_for_page(line.t, line.y);
  panels_.at(panel).lines.push_back(std::move(line));
}

void MultichannelTrace::add_phase_row(std::string name, std::vector<Phase> phases) {
  phase_rows_.emplace_back(std::move(name), std::move(phases));
}

void MultichannelTrace::add_event(Event event) {
  events_.push_back(std::move(event));
}

bool MultichannelTrace::empty() const {
  for (const auto& p : panels_)
    if (!p.lines.empty()) return false;
  return true;
}

MultichannelTrace::Range MultichannelTrace::time_range() const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& p : panels_)
    for (const auto& l : p.lines)
      for (double t : l.t)
        if (std::isfinite(t)) lo = std::min(lo, t), hi = std::max(hi, t);
  if (!std::isfinite(lo)) return {0, 1};
  if (!(hi - lo >= 1e-6 * std::max(1.0, std::abs(lo)))) hi = lo + 1.0;  // no span: one second
  const double step = nice_step(hi - lo, 10);
  return {nice_floor(lo, step), nice_ceil(hi, step)};
}

MultichannelTrace::Range MultichannelTrace::value_range(const Panel& p) const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& l : p.lines)
    for (double v : l.y)
      if (std::isfinite(v)) lo = std::min(lo, std::max(v, p.floor)), hi = std::max(hi, v);
  if (!std::isfinite(lo)) return {0, 1};
  // A flat channel still gets a readable axis (also where 1 is lost in a huge value).
  if (!(hi - lo >= std::max(1.0, 1e-6 * std::abs(lo))))
    hi = lo + std::max(1.0, 1e-6 * std::abs(lo));
  const double step = nice_step(hi - lo, 3);
  return {nice_floor(lo, step), nice_ceil(hi, step)};
}

double MultichannelTrace::x_of(const Range& t, double time) const {
  return kLeft + (time - t.lo) / (t.hi - t.lo) * (width_ - kLeft - kRight);
}

// One entry per recording (the lines' labels), in the order first drawn.
std::string MultichannelTrace::legend() const {
  std::vector<std::pair<std::string, std::string>> seen;
  for (const auto& p : panels_)
    for (const auto& l : p.lines)
      if (std::none_of(seen.begin(), seen.end(), [&](const auto& s) { return s.first == l.label; }))
        seen.emplace_back(l.label, l.color);
  std::ostringstream o;
  double x = kLeft;
  for (const auto& [label, color] : seen) {
    o << "<line x1=\"" << x << "\" y1=\"12\" x2=\"" << x + 24 << "\" y2=\"12\" stroke=\""
      << xml_escape(color) << "\" stroke-width=\"2\"/><text x=\"" << x + 30 << "\" y=\"16\">"
      << xml_escape(label) << "</text>\n";
    x += 40 + 7.0 * static_cast<double>(label.size());
  }
  return o.str();
}

std::string MultichannelTrace::phase_rows(const Range& t, double top) const {
  std::ostringstream o;
  for (const auto& [name, phases] : phase_rows_) {
    o << "<text x=\"" << kLeft - 8 << "\" y=\"" << top + 14 << "\" text-anchor=\"end\" "
      << "font-size=\"11\">" << xml_escape(name) << "</text>\n";
    for (const Phase& ph : phases) {
      const double x0 = x_of(t, std::max(ph.t0, t.lo)), x1 = x_of(t, std::min(ph.t1, t.hi));
      if (!(x1 > x0)) continue;
      o << "<g class=\"phase\"><rect x=\"" << num(x0) << "\" y=\"" << top + 2 << "\" width=\""
        << num(x1 - x0) << "\" height=\"" << kPhaseRow - 4 << "\" fill=\"" << xml_escape(ph.color)
        << "\" fill-opacity=\"0.35\"/><text x=\"" << num(x0 + 4) << "\" y=\"" << top + 14
        << "\" font-size=\"11\">" << xml_escape(ph.label) << "</text></g>\n";
    }
    top += kPhaseRow;
  }
  return o.str();
}

std::string MultichannelTrace::panel(const Panel& p, const Range& t, double top) const {
  const Range v = value_range(p);
  auto Y = [&](double y) { return top + kPanel - (y - v.lo) / (v.hi - v.lo) * kPanel; };
  std::ostringstream o;
  const double right = width_ - kRight;
  o << "<g class=\"panel\"><rect x=\"" << kLeft << "\" y=\"" << top << "\" width=\""
    << right - kLeft << "\" height=\"" << kPanel << "\" fill=\"none\" stroke=\"#999\"/>\n";
  o << "<text x=\"8\" y=\"" << top + kPanel / 2 - 2 << "\" font-weight=\"bold\">"
    << xml_escape(p.channel) << "</text><text x=\"8\" y=\"" << top + kPanel / 2 + 13
    << "\" font-size=\"11\" fill=\"#555\">" << xml_escape(p.unit) << "</text>\n";
  const double step = nice_step(v.hi - v.lo, 3);
  for (double y : axis_ticks(v.lo, v.hi, step))
    o << "<line x1=\"" << kLeft << "\" x2=\"" << right << "\" y1=\"" << num(Y(y)) << "\" y2=\""
      << num(Y(y)) << "\" stroke=\"#e4e4e4\"/><text x=\"" << kLeft - 4 << "\" y=\"" << num(Y(y) + 4)
      << "\" text-anchor=\"end\" font-size=\"11\">" << tick_label(y, step) << "</text>\n";
  for (const Line& l : p.lines) {
    std::string d;
    for (std::size_t i = 0; i < l.t.size() && i < l.y.size(); ++i)
      if (std::isfinite(l.t[i]) && std::isfinite(l.y[i]))
        d += (d.empty() ? "M" : " L") + num(x_of(t, l.t[i])) + ' ' +
             num(Y(std::max(l.y[i], p.floor)));
    if (d.empty()) continue;
    o << "<path class=\"series\" d=\"" << d << "\" fill=\"none\" stroke=\"" << xml_escape(l.color)
      << "\" stroke-width=\"1.6\"/>\n";
    if (l.radius > 0)
      for (std::size_t i = 0; i < l.t.size() && i < l.y.size(); ++i)
        o << "<circle cx=\"" << num(x_of(t, l.t[i])) << "\" cy=\""
          << num(Y(std::max(l.y[i], p.floor))) << "\" r=\"" << l.radius << "\" fill=\""
          << xml_escape(l.color) << "\"/>";
    o << "\n";
  }
  o << "</g>\n";
  return o.str();
}

// Numbered markers; numbers that would touch the previous one move down a row.
std::string MultichannelTrace::events(const Range& t, double top, double bottom) const {
  std::ostringstream o;
  double last_x = -1e9;
  int level = 0;
  for (std::size_t k = 0; k < events_.size(); ++k) {
    const Event& e = events_[k];
    if (e.t < t.lo || e.t > t.hi) continue;
    const double x = x_of(t, e.t);
    level = x - last_x < 18 ? (level + 1) % 2 : 0;
    last_x = x;
    const double cy = top + 8 + 14 * level;
    o << "<g class=\"event\"><line x1=\"" << num(x) << "\" x2=\"" << num(x) << "\" y1=\"" << cy + 7
      << "\" y2=\"" << bottom << "\" stroke=\"" << xml_escape(e.color)
      << "\" stroke-dasharray=\"3 3\"/><circle cx=\"" << num(x) << "\" cy=\"" << cy
      << "\" r=\"7\" fill=\"white\" stroke=\"" << xml_escape(e.color) << "\"/><text x=\"" << num(x)
      << "\" y=\"" << cy + 4 << "\" text-anchor=\"middle\" font-size=\"10\">" << k + 1
      << "</text></g>\n";
  }
  return o.str();
}

std::string MultichannelTrace::time_axis(const Range& t, double top, double bottom) const {
  std::ostringstream o;
  const double step = nice_step(t.hi - t.lo, 10);
  for (double s : axis_ticks(t.lo, t.hi, step))
    o << "<line x1=\"" << num(x_of(t, s)) << "\" x2=\"" << num(x_of(t, s)) << "\" y1=\"" << top
      << "\" y2=\"" << bottom << "\" stroke=\"#eeeeee\"/><text x=\"" << num(x_of(t, s)) << "\" y=\""
      << bottom + 16 << "\" text-anchor=\"middle\" font-size=\"11\">" << tick_label(s, step)
      << "</text>\n";
  o << "<text x=\"" << (kLeft + width_ - kRight) / 2 << "\" y=\"" << bottom + 36
    << "\" text-anchor=\"middle\">" << xml_escape(time_label_) << "</text>\n";
  return o.str();
}

std::string MultichannelTrace::render() const {
  const Range t = time_range();
  const double phases_top = kLegend, events_top = phases_top + kPhaseRow * phase_rows_.size();
  const double panels_top = events_top + kEventRow;
  const double panels_bottom = panels_top + panels_.size() * (kPanel + kGap) - kGap;
  const double height = panels_bottom + kAxis;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot trace\" id=\"" << xml_escape(id_)
    << "\" width=\"" << width_ << "\" height=\"" << height << "\" viewBox=\"0 0 " << width_ << ' '
    << height << "\" style=\"max-width:100%;height:auto\" font-family=\"sans-serif\" "
    << "font-size=\"12\" data-t-lo=\"" << num(t.lo) << "\" data-t-hi=\"" << num(t.hi)
    << "\" data-x-lo=\"" << num(x_of(t, t.lo)) << "\" data-x-hi=\"" << num(x_of(t, t.hi))
    << "\">\n<title>Multichannel urodynamic trace</title>\n<rect width=\"" << width_
    << "\" height=\"" << height << "\" fill=\"white\"/>\n";
  o << legend() << time_axis(t, panels_top, panels_bottom) << phase_rows(t, phases_top);
  double top = panels_top;
  for (const Panel& p : panels_) {
    o << panel(p, t, top);
    top += kPanel + kGap;
  }
  // A cursor the page's 3-D view moves to the time of the frame it shows (hidden until then).
  o << events(t, events_top, panels_bottom) << "<line id=\"" << xml_escape(id_)
    << "-cursor\" x1=\"0\" x2=\"0\" y1=\"" << num(panels_top) << "\" y2=\"" << num(panels_bottom)
    << "\" stroke=\"#d62728\" stroke-width=\"1.5\" visibility=\"hidden\"/>\n</svg>\n";
  return o.str();
}

}  // namespace vesica::compare
