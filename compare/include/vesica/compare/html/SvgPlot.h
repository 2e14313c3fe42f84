#pragma once
// A small, dependency-free x-y plot rendered as inline SVG for self-contained HTML reports.
// Any number of series (lines, points, or both), axis labels with units, a legend, and
// reference marks: horizontal/vertical lines, sloped lines y = a + b x, shaded bands and
// boxes. The axis ranges fit the data (with "nice" ticks) unless set; sloped lines and a
// box's volume extent never widen them; a series reaching the top tick gets one more
// step above it, so the frame does not hide a line drawn along the top. NaN values break a line.
// The <svg> scales down with its container (max-width 100 %), so a page never overflows a narrow
// window.
//
//   SvgPlot plot("Filling", "volume (ml)", "Pdet (cmH2O)");
//   plot.add_points("measured", v, p).add_line("simulated", vs, ps).add_hband(6, 10, "normal");
//   std::string svg = plot.render();
#include <optional>
#include <string>
#include <vector>

namespace vesica::compare {

class SvgPlot {
 public:
  // Area: x, y are a closed outline (a band: the upper curve, then the lower one backwards),
  // filled lightly under every line; a series without a label has no legend entry.
  enum class Style { Line, Points, LinePoints, Area };
  struct Series {
    std::string label;
    std::vector<double> x, y;
    Style style = Style::Line;
    std::string color;    // CSS colour; empty picks the next of the palette
    double width = 2.0;   // line width (px)
    double radius = 3.5;  // point radius (px)
    bool dashed = false;
    std::string dash = "";  // SVG stroke-dasharray ("2 3"); overrides `dashed`
  };
  // A horizontal (slope 0, no x) or vertical or sloped reference line, a band or a box.
  struct Mark {
    enum class Kind { HLine, VLine, Sloped, HBand, VBand, Box } kind;
    double a = 0, b = 0;  // HLine/VLine: a; Sloped: y = a + b x; bands, box x: [a, b]
    std::string label, color;
    double c = 0, d = 0;  // box y: [c, d]
  };

  SvgPlot(std::string title, std::string x_label, std::string y_label);

  SvgPlot& size(int width_px, int height_px);
  SvgPlot& id(std::string element_id);  // the svg's id (default: from the title)
  SvgPlot& x_range(double lo, double hi);
  SvgPlot& y_range(double lo, double hi);
  // Fitted axes never start below this (volumes, flows: not below 0).
  SvgPlot& y_floor(double lo);
  // The legend under the plot instead of at its right (for narrow plots).
  SvgPlot& legend_below();

  SvgPlot& add(Series series);
  SvgPlot& add_line(const std::string& label, const std::vector<double>& x,
                    const std::vector<double>& y, const std::string& color = {});
  SvgPlot& add_points(const std::string& label, const std::vector<double>& x,
                      const std::vector<double>& y, const std::string& color = {});
  SvgPlot& add_hline(double y, const std::string& label, const std::string& color = "#555");
  SvgPlot& add_vline(double x, const std::string& label, const std::string& color = "#555");
  SvgPlot& add_sloped_line(double intercept, double slope, const std::string& label,
                           const std::string& color = "#555");
  SvgPlot& add_hband(double y0, double y1, const std::string& label,
                     const std::string& color = "#8fbc8f");
  SvgPlot& add_vband(double x0, double x1, const std::string& label,
                     const std::string& color = "#8fbc8f");
  // The rectangle [x0, x1] x [y0, y1] (a normal range that holds over some volumes only).
  SvgPlot& add_box(double x0, double x1, double y0, double y1, const std::string& label,
                   const std::string& color = "#8fbc8f");

  bool empty() const { return series_.empty(); }
  std::string render() const;

 private:
  struct Range {
    double lo, hi;
  };
  Range data_range(bool x_axis) const;
  // The largest finite y of the series (not of the marks); -inf without data.
  double series_top() const;
  std::string legend(double x, double y, bool below) const;

  std::string title_, x_label_, y_label_, id_;
  int width_ = 720, height_ = 400;
  std::optional<Range> x_range_, y_range_;
  std::optional<double> y_floor_;
  bool legend_below_ = false;
  std::vector<Series> series_;
  std::vector<Mark> marks_;
};

// A line is drawn with at most about this many points: a page stays a page however long
// the recording (two million rows gave an 850 MB report). The data keep every sample.
inline constexpr std::size_t kMaxDrawnPoints = 4000;
// Thins a longer line to the lowest and highest point of each run of consecutive points,
// in their order, so that peaks (Qmax, a cough) survive.
void thin_for_page(std::vector<double>& x, std::vector<double>& y);

// Escapes &, <, >, " for XML/HTML text and attributes.
std::string xml_escape(const std::string& text);

// Axis helpers shared by the plots: a 1, 2 or 5 times a power of ten giving about `count`
// intervals over `span` (a span that is not a positive number gets 1); a tick label as
// short as the step allows; a coordinate.
double nice_step(double span, int count);
// The ticks lo, lo + step, ... up to hi, counted, never more than kMaxTicks: a loop that
// adds a step too small to change a large value would otherwise never end.
inline constexpr int kMaxTicks = 200;
std::vector<double> axis_ticks(double lo, double hi, double step);
// `value` rounded down / up to a multiple of `step`.
double nice_floor(double value, double step);
double nice_ceil(double value, double step);
std::string tick_label(double value, double step);
std::string svg_number(double value);

}  // namespace vesica::compare
