#pragma once
// A small, dependency-free x-y plot rendered as inline SVG for self-contained HTML reports.
// Any number of series (lines, points, or both), axis labels with units, a legend, and
// reference marks: horizontal/vertical lines, sloped lines y = a + b x, and shaded bands.
// The axis ranges fit the data (with "nice" ticks) unless set. NaN values break a line.
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
  enum class Style { Line, Points, LinePoints };
  struct Series {
    std::string label;
    std::vector<double> x, y;
    Style style = Style::Line;
    std::string color;    // CSS colour; empty picks the next of the palette
    double width = 2.0;   // line width (px)
    double radius = 3.5;  // point radius (px)
    bool dashed = false;
  };
  // A horizontal (slope 0, no x) or vertical or sloped reference line, or a band.
  struct Mark {
    enum class Kind { HLine, VLine, Sloped, HBand, VBand } kind;
    double a = 0, b = 0;  // HLine/VLine: a; Sloped: y = a + b x; bands: [a, b]
    std::string label, color;
  };

  SvgPlot(std::string title, std::string x_label, std::string y_label);

  SvgPlot& size(int width_px, int height_px);
  SvgPlot& id(std::string element_id);  // the svg's id (default: from the title)
  SvgPlot& x_range(double lo, double hi);
  SvgPlot& y_range(double lo, double hi);

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

  bool empty() const { return series_.empty(); }
  std::string render() const;

 private:
  struct Range {
    double lo, hi;
  };
  Range data_range(bool x_axis) const;

  std::string title_, x_label_, y_label_, id_;
  int width_ = 720, height_ = 400;
  std::optional<Range> x_range_, y_range_;
  std::vector<Series> series_;
  std::vector<Mark> marks_;
};

// Escapes &, <, >, " for XML/HTML text and attributes.
std::string xml_escape(const std::string& text);

}  // namespace vesica::compare
