// The report's three plots: filling Pdet against volume (no reference band: none with a
// published source was found), flow against time since the onset of flow,
// and pressure-flow with axes sized to the data and the nomogram lines of the patient's sex.
#include "report/ReportParts.h"
#include "vesica/compare/analysis/ModelComparison.h"
#include "vesica/compare/html/SvgPlot.h"

namespace vesica::compare::report {
namespace {

constexpr int kWidth = 580, kHeight = 340;

std::string figure(const SvgPlot& plot, const std::string& caption) {
  if (plot.empty()) return "<p class=\"missing\">" + xml_escape(caption) + ": no data.</p>\n";
  return "<figure>" + plot.render() + "<figcaption>" + caption + "</figcaption></figure>\n";
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
  SvgPlot plot("Filling: Pdet against volume", "bladder volume (ml)", "Pdet (cmH2O)");
  plot.id("plot-filling").size(kWidth, kHeight).legend_below();
  if (in.calibration)
    plot.add_vband(in.calibration->volume_lo_ml, in.calibration->volume_hi_ml, "fitted volumes",
                   "#cccccc");
  if (in.measured) {
    plot.add_points("measured", in.measured->filling.x, in.measured->filling.y, kMeasured);
    const Curve f = flagged_points(*in.measured);
    if (!f.x.empty()) plot.add_points("measured, flagged (left out)", f.x, f.y, kFlagged);
  }
  if (in.simulated)
    plot.add_line("simulated", in.simulated->filling.x, in.simulated->filling.y, kSimulated);
  if (in.calibration)
    plot.add(SvgPlot::Series{"fitted model", in.calibration->fitted_filling.x,
                             in.calibration->fitted_filling.y, SvgPlot::Style::Line, kFitted, 2.5,
                             3.5, true});
  return figure(plot, "Pdet during filling, from the start of filling to capacity.");
}

std::string flow_plot(const ReportInputs& in) {
  SvgPlot plot("Flow against time", "time since the onset of flow (s)", "flow (ml/s)");
  plot.id("plot-flow").size(kWidth, kHeight).legend_below().y_floor(0);
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
  std::string caption = "Uroflow from the onset of measurable flow";
  if (in.simulated) caption += "; simulated: " + simulated_voiding_label(in);
  // The calibrated model's flow, from its own onset: the curve the fit's Q(t) correlation
  // compares with the measured one.
  const auto* fitted =
      in.calibration && in.calibration->voiding ? &*in.calibration->voiding : nullptr;
  if (fitted && !fitted->simulated_flow_ml_s.x.empty()) {
    plot.add(SvgPlot::Series{"fitted model", fitted->simulated_flow_ml_s.x,
                             fitted->simulated_flow_ml_s.y, SvgPlot::Style::Line, kFitted, 2.5, 3.5,
                             true});
    caption += "; fitted model: the calibration's run, onsets aligned";
    if (fitted->flow_correlation)
      caption += " (correlation " + number(*fitted->flow_correlation) + ")";
  }
  return figure(plot, caption + ".");
}

// `dots`: mark every row (a clinical recording's sparse rows; not a simulation's history).
void add_pressure_flow(SvgPlot& plot, const RecordingAnalysis& a, const std::string& name,
                       const char* color, bool dots) {
  const auto& r = a.recording;
  if (!r.has_flow() || !r.has_pdet()) return;
  Curve c;
  for (std::size_t i = 0; i < r.rows(); ++i)
    if (r.flow_ml_s[i] > 0 && !a.flagged[i]) {
      c.x.push_back(r.flow_ml_s[i]);
      c.y.push_back(r.pdet_cmh2o(i));
    }
  if (c.x.empty()) return;
  plot.add(SvgPlot::Series{name, c.x, c.y, dots ? SvgPlot::Style::LinePoints : SvgPlot::Style::Line,
                           color, 1.5, 3});
  if (a.ics.qmax_ml_s && a.ics.pdet_qmax_cmh2o)
    plot.add(SvgPlot::Series{name + ": Qmax, PdetQmax",
                             {*a.ics.qmax_ml_s},
                             {*a.ics.pdet_qmax_cmh2o},
                             SvgPlot::Style::Points,
                             color,
                             2,
                             7});
}

// The nomogram of the patient's sex (SexSpecificCriteria.h), as lines Pdet = c + slope Q.
void add_nomogram(SvgPlot& plot, Sex sex) {
  if (sex == Sex::male) {
    plot.add_sloped_line(40, 2, "BOOI 40: obstructed above", "#8b0000");
    plot.add_sloped_line(20, 2, "BOOI 20: unobstructed below", "#e9967a");
    plot.add_sloped_line(150, -5, "BCI 150: strong above", "#006400");
    plot.add_sloped_line(100, -5, "BCI 100: weak below", "#66cdaa");
  } else if (sex == Sex::female) {
    plot.add_sloped_line(18, 2.2, "BOOIf 18: obstruction almost certain above", "#8b0000");
    plot.add_sloped_line(5, 2.2, "BOOIf 5: obstruction likely above", "#e9967a");
    plot.add_sloped_line(0, 2.2, "BOOIf 0: obstruction unlikely below", "#66cdaa");
  }
}

std::string pressure_flow_plot(const ReportInputs& in) {
  SvgPlot plot("Pressure-flow", "flow Q (ml/s)", "Pdet (cmH2O)");
  plot.id("plot-pressure-flow").size(kWidth, kHeight + 40).legend_below();
  if (in.measured) add_pressure_flow(plot, *in.measured, "measured", kMeasured, true);
  if (in.simulated) add_pressure_flow(plot, *in.simulated, "simulated", kSimulated, false);
  add_nomogram(plot, in.patient.sex);
  // Each line's source, in short; the full references are under the criteria table.
  const char* lines =
      in.patient.sex == Sex::male
          ? " with the ICS nomogram lines for men (Abrams, BJU Int 1999;84:14-15)."
      : in.patient.sex == Sex::female
          ? " with the BOOIf lines for women (Solomon et al., Neurourol Urodyn 2018;37:368-378)."
          : "; sex not stated, so no nomogram.";
  std::string caption = std::string("Pdet against flow while voiding (unflagged rows)") + lines;
  if (in.simulated) caption += " Simulated: " + simulated_voiding_label(in) + ".";
  return figure(plot, caption);
}

}  // namespace

std::string plots_section(const ReportInputs& in) {
  return "<div class=\"plots\">\n" + filling_plot(in) + flow_plot(in) + pressure_flow_plot(in) +
         "</div>\n";
}

}  // namespace vesica::compare::report
