// SvgPlot: data land where the axis mapping says, every element kind is emitted, text is
// escaped.
#include <algorithm>
#include <cmath>
#include <regex>

#include <gtest/gtest.h>

#include "vesica/compare/html/SvgPlot.h"

using vesica::compare::SvgPlot;

TEST(SvgPlot, MapsDataIntoThePlotArea) {
  // 720 x 400 with margins left 64, right 230, top 34, bottom 48: plot area 426 x 318
  SvgPlot plot("t", "x (ml)", "y (cmH2O)");
  plot.x_range(0, 10).y_range(0, 100).add_points("p", {0, 10, 5}, {0, 100, 50});
  const std::string svg = plot.render();
  EXPECT_NE(svg.find("cx=\"64.00\" cy=\"352.00\""), std::string::npos) << svg;   // (0, 0)
  EXPECT_NE(svg.find("cx=\"490.00\" cy=\"34.00\""), std::string::npos) << svg;   // (10, 100)
  EXPECT_NE(svg.find("cx=\"277.00\" cy=\"193.00\""), std::string::npos) << svg;  // (5, 50)
}

TEST(SvgPlot, EmitsSeriesMarksLegendAndLabels) {
  SvgPlot plot("A <title>", "volume (ml)", "Pdet (cmH2O)");
  plot.add_line("sim", {0, 1, 2}, {0, 1, 4})
      .add_points("meas", {0.5}, {0.5})
      .add_hline(2, "h")
      .add_vline(1, "v")
      .add_sloped_line(0, 1, "slope")
      .add_hband(1, 2, "hb")
      .add_vband(0.2, 0.4, "vb");
  const std::string svg = plot.render();
  EXPECT_EQ(std::count(svg.begin(), svg.end(), '\n') > 10, true);
  const auto count = [&](const std::string& what) {
    const std::regex re(what);
    return std::distance(std::sregex_iterator(svg.begin(), svg.end(), re), std::sregex_iterator());
  };
  EXPECT_EQ(count("<path class=\"series\""), 1);
  EXPECT_EQ(count("<circle class=\"series\""), 1);
  EXPECT_EQ(count("<path class=\"reference\""), 3);
  EXPECT_EQ(count("<rect class=\"band\""), 2);
  EXPECT_NE(svg.find("A &lt;title&gt;"), std::string::npos);
  EXPECT_NE(svg.find(">volume (ml)<"), std::string::npos);
  EXPECT_NE(svg.find(">Pdet (cmH2O)<"), std::string::npos);
  EXPECT_NE(svg.find(">slope<"), std::string::npos);  // legend entry for a mark
}

TEST(SvgPlot, NaNBreaksALine) {
  SvgPlot plot("gap", "x", "y");
  plot.add_line("l", {0, 1, 2, 3}, {0, 1, std::nan(""), 3});
  const std::string svg = plot.render();
  const auto path = svg.substr(svg.find("<path class=\"series\""));
  EXPECT_EQ(std::count(path.begin(), path.begin() + path.find("/>"), 'M'), 2);
}

TEST(SvgPlot, ALineAlongTheTopTickIsNotHiddenByTheFrame) {
  // Pdet 0..25 cmH2O: ticks every 5; a plateau at 25 would lie on the frame's top edge, so
  // the axis goes one step on, to 30, and the plateau is drawn at 34 + 318 (1 - 25/30) = 87.
  SvgPlot top("plateau", "Q (ml/s)", "Pdet (cmH2O)");
  top.add_line("sim", {0, 5, 10}, {0, 25, 25});
  const std::string svg = top.render();
  EXPECT_NE(svg.find(">30<"), std::string::npos) << svg;
  EXPECT_NE(svg.find("87.00"), std::string::npos) << svg;
  // a series below the top tick keeps the tight axis: 0..24 ends at 25
  SvgPlot below("below", "Q (ml/s)", "Pdet (cmH2O)");
  below.add_line("sim", {0, 5, 10}, {0, 24, 24});
  const std::string tight = below.render();
  EXPECT_NE(tight.find(">25<"), std::string::npos);
  EXPECT_EQ(tight.find(">30<"), std::string::npos);
}

TEST(SvgPlot, AMillionPointRecordingIsDrawnWithAFewThousandKeepingItsPeak) {
  // Default 720 x 400: y = 90 of [0, 100] is at 34 + 318 - 0.9 * 318 = 65.80 px.
  std::vector<double> x(1000000), y(1000000, 10.0);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i) * 0.01;
  y[654321] = 90.0;  // one sample of Qmax
  SvgPlot plot("flow", "time (s)", "flow (ml/s)");
  plot.y_range(0, 100).add_line("flow", x, y);
  const std::string svg = plot.render();
  const std::string::difference_type segments =
      std::count(svg.begin(), svg.end(), 'L');  // one "L" per drawn point after the first
  EXPECT_LE(segments, 4100);
  EXPECT_NE(svg.find(" 65.80"), std::string::npos);
  EXPECT_LT(svg.size(), 200000u);
}
