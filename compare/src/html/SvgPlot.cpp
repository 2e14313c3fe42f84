#include "vesica/compare/html/SvgPlot.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace vesica::compare {
namespace {

const char* kPalette[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e",
                          "#9467bd", "#8c564b", "#e377c2", "#17becf"};

std::string num(double v) {
  return svg_number(v);
}

std::string dash_attribute(const SvgPlot::Series& s) {
  if (!s.dash.empty()) return " stroke-dasharray=\"" + xml_escape(s.dash) + "\"";
  return s.dashed ? " stroke-dasharray=\"8 4\"" : "";
}

std::string slug(const std::string& s) {
  std::string out;
  for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return "plot-" + out;
}

}  // namespace

std::string svg_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  return buf;
}

std::string tick_label(double v, double step) {
  char buf[32];
  const int decimals = step >= 1 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(buf, sizeof buf, "%.*f", decimals, std::abs(v) < 1e-9 * step ? 0.0 : v);
  return buf;
}

double nice_step(double span, int count) {
  if (!(span > 0.0) || !std::isfinite(span) || count < 1) return 1.0;
  const double raw = span / count;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (raw <= m * p) return m * p;
  return 10 * p;
}

void thin_for_page(std::vector<double>& x, std::vector<double>& y) {
  const std::size_t n = std::min(x.size(), y.size());
  if (n <= kMaxDrawnPoints) return;
  const std::size_t run = (n + kMaxDrawnPoints / 2 - 1) / (kMaxDrawnPoints / 2);
  std::vector<double> tx, ty;
  for (std::size_t start = 0; start < n; start += run) {
    const std::size_t end = std::min(n, start + run);
    std::size_t lo = start, hi = start;
    for (std::size_t i = start; i < end; ++i) {
      if (y[i] < y[lo]) lo = i;
      if (y[i] > y[hi]) hi = i;
    }
    const std::size_t first = std::min(lo, hi), last = std::max(lo, hi);
    tx.push_back(x[first]);
    ty.push_back(y[first]);
    if (last != first) {
      tx.push_back(x[last]);
      ty.push_back(y[last]);
    }
  }
  x.swap(tx);
  y.swap(ty);
}

std::vector<double> axis_ticks(double lo, double hi, double step) {
  std::vector<double> ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(step > 0.0)) return ticks;
  for (int k = 0; k < kMaxTicks; ++k) {
    const double t = lo + k * step;
    if (t > hi + 1e-9 * step) break;
    ticks.push_back(t);
  }
  return ticks;
}

// A rounding residue (1e-13 past a tick) does not add a whole step to the axis.
double nice_floor(double value, double step) {
  return std::floor(value / step + 1e-9) * step;
}
double nice_ceil(double value, double step) {
  return std::ceil(value / step - 1e-9) * step;
}

std::string xml_escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

SvgPlot::SvgPlot(std::string title, std::string x_label, std::string y_label)
    : title_(std::move(title)), x_label_(std::move(x_label)), y_label_(std::move(y_label)) {
  id_ = slug(title_);
}

SvgPlot& SvgPlot::size(int w, int h) {
  width_ = w;
  height_ = h;
  return *this;
}
SvgPlot& SvgPlot::id(std::string element_id) {
  id_ = std::move(element_id);
  return *this;
}
SvgPlot& SvgPlot::x_range(double lo, double hi) {
  x_range_ = Range{lo, hi};
  return *this;
}
SvgPlot& SvgPlot::y_range(double lo, double hi) {
  y_range_ = Range{lo, hi};
  return *this;
}
SvgPlot& SvgPlot::y_floor(double lo) {
  y_floor_ = lo;
  return *this;
}
SvgPlot& SvgPlot::legend_below() {
  legend_below_ = true;
  return *this;
}

SvgPlot& SvgPlot::add(Series s) {
  thin_for_page(s.x, s.y);
  if (s.color.empty()) s.color = kPalette[series_.size() % (sizeof kPalette / sizeof *kPalette)];
  series_.push_back(std::move(s));
  return *this;
}
SvgPlot& SvgPlot::add_line(const std::string& label, const std::vector<double>& x,
                           const std::vector<double>& y, const std::string& color) {
  return add(Series{label, x, y, Style::Line, color});
}
SvgPlot& SvgPlot::add_points(const std::string& label, const std::vector<double>& x,
                             const std::vector<double>& y, const std::string& color) {
  return add(Series{label, x, y, Style::Points, color});
}
SvgPlot& SvgPlot::add_hline(double y, const std::string& label, const std::string& color) {
  marks_.push_back({Mark::Kind::HLine, y, 0, label, color});
  return *this;
}
SvgPlot& SvgPlot::add_vline(double x, const std::string& label, const std::string& color) {
  marks_.push_back({Mark::Kind::VLine, x, 0, label, color});
  return *this;
}
SvgPlot& SvgPlot::add_sloped_line(double a, double b, const std::string& label,
                                  const std::string& color) {
  marks_.push_back({Mark::Kind::Sloped, a, b, label, color});
  return *this;
}
SvgPlot& SvgPlot::add_hband(double y0, double y1, const std::string& label,
                            const std::string& color) {
  marks_.push_back({Mark::Kind::HBand, y0, y1, label, color});
  return *this;
}
SvgPlot& SvgPlot::add_vband(double x0, double x1, const std::string& label,
                            const std::string& color) {
  marks_.push_back({Mark::Kind::VBand, x0, x1, label, color});
  return *this;
}
SvgPlot& SvgPlot::add_box(double x0, double x1, double y0, double y1, const std::string& label,
                          const std::string& color) {
  marks_.push_back({Mark::Kind::Box, x0, x1, label, color, y0, y1});
  return *this;
}

double SvgPlot::series_top() const {
  double top = -std::numeric_limits<double>::infinity();
  for (const auto& s : series_)
    for (double v : s.y)
      if (std::isfinite(v)) top = std::max(top, v);
  return top;
}

SvgPlot::Range SvgPlot::data_range(bool x_axis) const {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& s : series_)
    for (double v : x_axis ? s.x : s.y)
      if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  for (const auto& m : marks_) {
    const bool on_axis = x_axis ? (m.kind == Mark::Kind::VLine || m.kind == Mark::Kind::VBand)
                                : (m.kind == Mark::Kind::HLine || m.kind == Mark::Kind::HBand);
    if (m.kind == Mark::Kind::Box && !x_axis) {  // its pressures, not its volumes
      lo = std::min({lo, m.c, m.d}), hi = std::max({hi, m.c, m.d});
      continue;
    }
    if (!on_axis) continue;
    lo = std::min(lo, m.a), hi = std::max(hi, m.a);
    if (m.kind == Mark::Kind::VBand || m.kind == Mark::Kind::HBand)
      lo = std::min(lo, m.b), hi = std::max(hi, m.b);
  }
  if (!std::isfinite(lo)) return {0, 1};
  if (!x_axis && y_floor_) lo = std::max(lo, *y_floor_), hi = std::max(hi, lo);
  if (hi - lo < 1e-12) return {x_axis || !y_floor_ ? lo - 1 : lo, hi + 1};
  return {lo, hi};
}

std::string SvgPlot::render() const {
  std::size_t entries = 0;
  for (const auto& s : series_) entries += s.label.empty() ? 0 : 1;
  for (const auto& m : marks_) entries += m.label.empty() ? 0 : 1;
  const int left = 64, right = legend_below_ ? 16 : 230, top = 34, bottom = 48;
  const int legend_height = legend_below_ ? 18 * static_cast<int>(entries) + 16 : 0;
  const int height = height_ + legend_height;
  const double pw = width_ - left - right, ph = height_ - top - bottom;
  Range xr = x_range_ ? *x_range_ : data_range(true);
  Range yr = y_range_ ? *y_range_ : data_range(false);
  const double xs = nice_step(xr.hi - xr.lo, 6), ys = nice_step(yr.hi - yr.lo, 5);
  if (!x_range_) xr = {nice_floor(xr.lo, xs), nice_ceil(xr.hi, xs)};
  if (!y_range_) {
    yr = {nice_floor(yr.lo, ys), nice_ceil(yr.hi, ys)};
    if (series_top() > yr.hi - 0.01 * (yr.hi - yr.lo)) yr.hi += ys;
  }
  auto X = [&](double x) { return left + (x - xr.lo) / (xr.hi - xr.lo) * pw; };
  auto Y = [&](double y) { return top + ph - (y - yr.lo) / (yr.hi - yr.lo) * ph; };

  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"plot\" id=\"" << xml_escape(id_)
    << "\" width=\"" << width_ << "\" height=\"" << height << "\" viewBox=\"0 0 " << width_ << ' '
    << height << "\" style=\"max-width:100%;height:auto\" font-family=\"sans-serif\" "
    << "font-size=\"12\">\n";
  o << "<title>" << xml_escape(title_) << "</title>\n";
  o << "<defs><clipPath id=\"" << xml_escape(id_) << "-clip\"><rect x=\"" << left << "\" y=\""
    << top << "\" width=\"" << pw << "\" height=\"" << ph << "\"/></clipPath></defs>\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << width_ << "\" height=\"" << height
    << "\" fill=\"white\"/>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"20\" text-anchor=\"middle\" font-size=\"14\" "
    << "font-weight=\"bold\">" << xml_escape(title_) << "</text>\n";
  // grid and ticks
  o << "<g class=\"axes\" stroke=\"#ddd\">\n";
  for (double t : axis_ticks(xr.lo, xr.hi, xs))
    o << "<line x1=\"" << num(X(t)) << "\" y1=\"" << top << "\" x2=\"" << num(X(t)) << "\" y2=\""
      << top + ph << "\"/><text x=\"" << num(X(t)) << "\" y=\"" << top + ph + 16
      << "\" text-anchor=\"middle\" stroke=\"none\" fill=\"#333\">" << tick_label(t, xs)
      << "</text>\n";
  for (double t : axis_ticks(yr.lo, yr.hi, ys))
    o << "<line x1=\"" << left << "\" y1=\"" << num(Y(t)) << "\" x2=\"" << left + pw << "\" y2=\""
      << num(Y(t)) << "\"/><text x=\"" << left - 6 << "\" y=\"" << num(Y(t) + 4)
      << "\" text-anchor=\"end\" stroke=\"none\" fill=\"#333\">" << tick_label(t, ys)
      << "</text>\n";
  o << "</g>\n<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"#333\"/>\n";
  o << "<text x=\"" << left + pw / 2 << "\" y=\"" << height_ - 8 << "\" text-anchor=\"middle\">"
    << xml_escape(x_label_) << "</text>\n";
  o << "<text transform=\"translate(16," << top + ph / 2
    << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(y_label_) << "</text>\n";

  // marks under the data, clipped to the plot area
  o << "<g clip-path=\"url(#" << xml_escape(id_) << "-clip)\">\n";
  for (const auto& m : marks_) {
    const std::string c = xml_escape(m.color);
    switch (m.kind) {
      case Mark::Kind::HBand:
        o << "<rect class=\"band\" x=\"" << left << "\" width=\"" << pw << "\" y=\""
          << num(Y(std::max(m.a, m.b))) << "\" height=\"" << num(std::abs(Y(m.a) - Y(m.b)))
          << "\" fill=\"" << c << "\" fill-opacity=\"0.25\"/>\n";
        break;
      case Mark::Kind::VBand:
        o << "<rect class=\"band\" y=\"" << top << "\" height=\"" << ph << "\" x=\""
          << num(X(std::min(m.a, m.b))) << "\" width=\"" << num(std::abs(X(m.b) - X(m.a)))
          << "\" fill=\"" << c << "\" fill-opacity=\"0.25\"/>\n";
        break;
      case Mark::Kind::HLine:
        o << "<path class=\"reference\" d=\"M" << left << ' ' << num(Y(m.a)) << " H" << left + pw
          << "\" stroke=\"" << c << "\" stroke-dasharray=\"6 4\"/>\n";
        break;
      case Mark::Kind::VLine:
        o << "<path class=\"reference\" d=\"M" << num(X(m.a)) << ' ' << top << " V" << top + ph
          << "\" stroke=\"" << c << "\" stroke-dasharray=\"6 4\"/>\n";
        break;
      case Mark::Kind::Sloped:
        o << "<path class=\"reference\" d=\"M" << num(X(xr.lo)) << ' ' << num(Y(m.a + m.b * xr.lo))
          << " L" << num(X(xr.hi)) << ' ' << num(Y(m.a + m.b * xr.hi)) << "\" stroke=\"" << c
          << "\" stroke-dasharray=\"6 4\"/>\n";
        break;
      case Mark::Kind::Box:
        o << "<rect class=\"band\" x=\"" << num(X(std::min(m.a, m.b))) << "\" width=\""
          << num(std::abs(X(m.b) - X(m.a))) << "\" y=\"" << num(Y(std::max(m.c, m.d)))
          << "\" height=\"" << num(std::abs(Y(m.c) - Y(m.d))) << "\" fill=\"" << c
          << "\" fill-opacity=\"0.3\" stroke=\"" << c << "\"/>\n";
        break;
    }
  }
  for (const auto& s : series_) {  // areas under the lines
    if (s.style != Style::Area) continue;
    std::string d;
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
        d += (d.empty() ? "M" : " L") + num(X(s.x[i])) + ' ' + num(Y(s.y[i]));
    if (!d.empty())
      o << "<path class=\"area\" d=\"" << d << " Z\" fill=\"" << xml_escape(s.color)
        << "\" fill-opacity=\"0.18\" stroke=\"none\"/>\n";
  }
  for (const auto& s : series_) {
    const std::string c = xml_escape(s.color);
    if (s.style == Style::Area) continue;
    if (s.style != Style::Points) {
      std::string d;
      bool pen_down = false;
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
          pen_down = false;
          continue;
        }
        d += (pen_down ? " L" : " M") + num(X(s.x[i])) + ' ' + num(Y(s.y[i]));
        pen_down = true;
      }
      if (!d.empty())
        o << "<path class=\"series\" d=\"" << d << "\" fill=\"none\" stroke=\"" << c
          << "\" stroke-width=\"" << s.width << "\"" << dash_attribute(s) << "/>\n";
    }
    if (s.style != Style::Line)
      for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i]))
          o << "<circle class=\"series\" cx=\"" << num(X(s.x[i])) << "\" cy=\"" << num(Y(s.y[i]))
            << "\" r=\"" << s.radius << "\" fill=\"" << c << "\"/>\n";
  }
  o << "</g>\n";

  o << legend(legend_below_ ? left : left + pw + 14, legend_below_ ? height_ + 14 : top + 10,
              legend_below_);
  o << "</svg>\n";
  return o.str();
}

// One entry per series and per labelled mark: in a column at the right, or in two columns
// under the plot.
std::string SvgPlot::legend(double x0, double y0, bool below) const {
  std::ostringstream o;
  o << "<g class=\"legend\">\n";
  // Two columns under the plot when every label fits half the width (about 7 px a letter).
  std::size_t longest = 0;
  for (const auto& s : series_) longest = std::max(longest, s.label.size());
  for (const auto& m : marks_) longest = std::max(longest, m.label.size());
  const std::size_t columns = below && 26 + 7.0 * longest < (width_ - x0) / 2 ? 2 : 1;
  std::size_t k = 0;
  auto at = [&](double& lx, double& ly) {
    const std::size_t row = k / columns, column = k % columns;
    lx = x0 + static_cast<double>(column) * (width_ - x0) / 2;
    ly = y0 + 18.0 * static_cast<double>(row);
    ++k;
  };
  double lx = 0, ly = 0;
  for (const auto& s : series_) {
    if (s.label.empty()) continue;
    at(lx, ly);
    const std::string c = xml_escape(s.color);
    if (s.style == Style::Area)
      o << "<rect x=\"" << lx << "\" y=\"" << ly - 10 << "\" width=\"20\" height=\"10\" fill=\""
        << c << "\" fill-opacity=\"0.18\"/>";
    else if (s.style == Style::Points)
      o << "<circle cx=\"" << lx + 10 << "\" cy=\"" << ly - 4 << "\" r=\""
        << std::min(s.radius, 6.0) << "\" fill=\"" << c << "\"/>";
    else
      o << "<line x1=\"" << lx << "\" y1=\"" << ly - 4 << "\" x2=\"" << lx + 20 << "\" y2=\""
        << ly - 4 << "\" stroke=\"" << c << "\" stroke-width=\"" << s.width << "\""
        << dash_attribute(s) << "/>";
    o << "<text x=\"" << lx + 26 << "\" y=\"" << ly << "\">" << xml_escape(s.label) << "</text>\n";
  }
  for (const auto& m : marks_) {
    if (m.label.empty()) continue;
    at(lx, ly);
    const std::string c = xml_escape(m.color);
    if (m.kind == Mark::Kind::HBand || m.kind == Mark::Kind::VBand || m.kind == Mark::Kind::Box)
      o << "<rect x=\"" << lx << "\" y=\"" << ly - 10 << "\" width=\"20\" height=\"10\" fill=\""
        << c << "\" fill-opacity=\"0.3\"/>";
    else
      o << "<line x1=\"" << lx << "\" y1=\"" << ly - 4 << "\" x2=\"" << lx + 20 << "\" y2=\""
        << ly - 4 << "\" stroke=\"" << c << "\" stroke-dasharray=\"6 4\"/>";
    o << "<text x=\"" << lx + 26 << "\" y=\"" << ly << "\">" << xml_escape(m.label) << "</text>\n";
  }
  o << "</g>\n";
  return o.str();
}

}  // namespace vesica::compare
