#include "vesica/compare/calibration/CalibrationTargets.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "vesica/compare/analysis/PiecewiseLinear.h"

namespace vesica::compare {
namespace {

constexpr double kPressureScale = 1.0;  // cmH2O: recordings give whole cmH2O
// cmH2O: Pdet while voiding is the difference of two channels that the voiding's straining
// moves by several cmH2O (Pabd swings of 10 cmH2O and more), which a model with a resting
// abdomen does not reproduce: it weighs as a reading that uncertain.
constexpr double kVoidingPressureScale = 5.0;
constexpr double kFlowScale = 1.0;     // ml/s: uroflowmeters give whole ml/s
constexpr double kVoidedScale = 10.0;  // ml: one reading, as heavy as a few flow rows
// s: the onset of flow is read off to the recording's row spacing of a few seconds
constexpr double kOnsetScale = 2.0;
// The ICS read-outs a urologist reports, each one number, weighed as a few readings: Qmax
// as one flow reading (the readings around it are its plateau, which a least-squares fit of
// the curve alone would match instead of the maximum), PdetQmax to a cmH2O and a half (the
// readings' whole-cmH2O rounding and the straining's transmission error; docs/compare.md
// says how it was chosen), the flow time to a tenth of a normal one.
constexpr double kQmaxScale = 1.0;      // ml/s
constexpr double kPdetQmaxScale = 1.5;  // cmH2O
constexpr double kFlowTimeScale = 4.0;  // s
// A run "reaches" a volume within this (it stops at capacity to the Newton tolerance).
constexpr double kReachToleranceMl = 0.01;

const double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string number(double v) {
  std::ostringstream o;
  o.precision(4);
  o << v;
  return o.str();
}

// The curves of a simulated run, read without artefact flags (a model does not cough).
struct SimulatedCurves {
  Curve filling;                  // Pdet(V) from the start to capacity
  std::optional<double> onset_s;  // onset of flow (docs/physics.md §7.3)
  double capacity_s = 0;          // time of the end of filling
  Curve flow_t, pdet_t;           // against the time since the onset, to the end of the run
  Curve flow_v, pdet_v;           // against the voided volume, from capacity on
  double voided_ml = 0;           // at the end of the run
  IcsParameters ics;              // its ICS read-outs
};

SimulatedCurves simulated_curves(const Recording& r) {
  SimulatedCurves c;
  if (r.rows() == 0) return c;
  const IcsParameters ics = compute_ics(r, {});
  c.ics = ics;
  c.filling = filling_curve(r, ics, std::vector<bool>(r.rows(), false));
  const std::vector<double> voided = r.voided_or_integrated_ml();
  c.voided_ml = voided.back();
  const bool flow = r.has_flow();
  for (std::size_t i = ics.capacity_row; i < r.rows(); ++i) {
    c.pdet_v.x.push_back(voided[i]);
    c.pdet_v.y.push_back(r.pdet_cmh2o(i));
    c.flow_v.x.push_back(voided[i]);
    c.flow_v.y.push_back(flow ? r.flow_ml_s[i] : 0.0);
  }
  c.onset_s = ics.voiding_start_s;
  if (r.has_time()) c.capacity_s = r.time_s[ics.capacity_row];
  if (!c.onset_s) return c;
  for (std::size_t i = 0; i < r.rows(); ++i) {
    if (r.time_s[i] < *c.onset_s) continue;
    c.flow_t.x.push_back(r.time_s[i] - *c.onset_s);
    c.flow_t.y.push_back(r.flow_ml_s[i]);
    c.pdet_t.x.push_back(r.time_s[i] - *c.onset_s);
    c.pdet_t.y.push_back(r.pdet_cmh2o(i));
  }
  return c;
}

double last_x(const Curve& c) {
  return c.x.empty() ? -HUGE_VAL : *std::max_element(c.x.begin(), c.x.end());
}

// Values of the run at the series' abscissae, NaN where not compared; nullopt and a reason
// when the run stopped before the data's end.
struct SeriesValues {
  std::vector<double> y;
  std::string failure;  // empty: usable
};

std::string stopped(const ModelRun& run) {
  return run.completed ? std::string() : " (" + run.failure + ")";
}

SeriesValues filling_values(const TargetSeries& s, const SimulatedCurves& c, const ModelRun& run) {
  SeriesValues v;
  const double need = *std::max_element(s.x.begin(), s.x.end());
  const double reached = last_x(c.filling);
  if (c.filling.x.size() < 2 || reached < need - kReachToleranceMl) {
    v.failure = "the run stopped at " + number(std::max(reached, 0.0)) +
                " ml, before the data's last volume " + number(need) + " ml" + stopped(run);
    return v;
  }
  const PiecewiseLinear f(c.filling.x, c.filling.y);
  for (double x : s.x) v.y.push_back(f(x));
  return v;
}

// Beyond the end of a completed run's voiding (later than its flow, or more voided than it
// voided) its flow is zero: a measured flow there is a true misfit, which keeps a run that
// voids too little from looking better for being compared at fewer readings. Its pressure
// there is unknown (not compared).
double after_end(const TargetSeries& s) {
  return s.quantity == Quantity::Flow ? 0.0 : kNaN;
}

SeriesValues voiding_values(const TargetSeries& s, const Curve& curve, const ModelRun& run,
                            const char* unit) {
  SeriesValues v;
  const double need = *std::max_element(s.x.begin(), s.x.end());
  const double end = last_x(curve);
  if (!run.completed && end < need) {
    v.failure = (curve.x.empty() ? std::string("the run stopped before any flow")
                                 : "the run stopped at " + number(end) + " " + unit) +
                ", before the data's last reading at " + number(need) + " " + unit + stopped(run);
    return v;
  }
  if (curve.x.size() < 2) {
    v.y.assign(s.x.size(), after_end(s));  // a completed run that never voided
    return v;
  }
  const PiecewiseLinear f(curve.x, curve.y);
  for (double x : s.x) v.y.push_back(x <= end ? f(x) : after_end(s));
  return v;
}

// A completed run's single read-out: a run that never voided has voided nothing, in no
// time and at no flow (true misfits), and no PdetQmax (not compared).
double ics_value(Quantity q, const SimulatedCurves& c) {
  const bool flowed = c.ics.qmax_ml_s && *c.ics.qmax_ml_s > 0.0;
  switch (q) {
    case Quantity::MaximumFlow:
      return flowed ? *c.ics.qmax_ml_s : 0.0;
    case Quantity::PdetAtMaximumFlow:
      return flowed && c.ics.pdet_qmax_cmh2o ? *c.ics.pdet_qmax_cmh2o : kNaN;
    case Quantity::FlowTime:
      return flowed && c.ics.flow_time_s ? *c.ics.flow_time_s : 0.0;
    default:
      return c.voided_ml;
  }
}

SeriesValues series_values(const TargetSeries& s, const SimulatedCurves& c, const ModelRun& run) {
  switch (s.abscissa) {
    case Abscissa::BladderVolume:
      return filling_values(s, c, run);
    case Abscissa::TimeSinceFlowOnset:
      return voiding_values(s, s.quantity == Quantity::Flow ? c.flow_t : c.pdet_t, run,
                            "s after the onset of flow");
    case Abscissa::VoidedVolume:
      return voiding_values(s, s.quantity == Quantity::Flow ? c.flow_v : c.pdet_v, run,
                            "ml voided");
    case Abscissa::None:
      break;
  }
  SeriesValues v;
  if (s.quantity == Quantity::OnsetDelay) {
    // A run that never opened its urethra has no onset: not compared (its flow is).
    if (c.onset_s)
      v.y = {*c.onset_s - c.capacity_s};
    else if (run.completed)
      v.y = {kNaN};
    else
      v.failure = "the run stopped before the onset of flow" + stopped(run);
    return v;
  }
  if (!run.completed) {
    v.failure = "the run stopped before the end of voiding" + stopped(run);
    return v;
  }
  v.y = {ics_value(s.quantity, c)};
  return v;
}

TargetSeries series(std::string name, Quantity q, Abscissa a, double scale) {
  TargetSeries s;
  s.name = std::move(name);
  s.quantity = q;
  s.abscissa = a;
  s.scale = scale;
  return s;
}

void add_if_any(TargetSeries s, CalibrationTargets& t) {
  if (!s.x.empty()) t.series.push_back(std::move(s));
}

void add_timed_voiding(const RecordingAnalysis& m, CalibrationTargets& t) {
  const Recording& r = m.recording;
  const double onset = *m.ics.voiding_start_s;
  std::size_t last_flow = 0;
  for (std::size_t i = 0; i < r.rows(); ++i)
    if (r.flow_ml_s[i] > 0) last_flow = i;
  TargetSeries q = series("voiding flow", Quantity::Flow, Abscissa::TimeSinceFlowOnset, kFlowScale);
  TargetSeries p =
      series("voiding Pdet", Quantity::Pdet, Abscissa::TimeSinceFlowOnset, kVoidingPressureScale);
  for (std::size_t i = 0; i < r.rows(); ++i) {
    if (r.time_s[i] < onset) continue;
    q.x.push_back(r.time_s[i] - onset);
    q.y.push_back(r.flow_ml_s[i]);
    if (m.flagged[i] || i > last_flow || !r.has_pdet()) continue;
    p.x.push_back(r.time_s[i] - onset);
    p.y.push_back(r.pdet_cmh2o(i));
  }
  add_if_any(std::move(q), t);
  add_if_any(std::move(p), t);
}

// A voiding table without time: Pdet (and flow) against the voided volume.
void add_volume_voiding(const RecordingAnalysis& m, CalibrationTargets& t) {
  const Recording& r = m.recording;
  const std::vector<double> voided = r.voided_or_integrated_ml();
  TargetSeries p =
      series("voiding Pdet", Quantity::Pdet, Abscissa::VoidedVolume, kVoidingPressureScale);
  TargetSeries q = series("voiding flow", Quantity::Flow, Abscissa::VoidedVolume, kFlowScale);
  for (std::size_t i = m.ics.capacity_row; i < r.rows(); ++i) {
    if (r.has_flow()) {
      q.x.push_back(voided[i]);
      q.y.push_back(r.flow_ml_s[i]);
    }
    if (m.flagged[i] || !r.has_pdet()) continue;
    p.x.push_back(voided[i]);
    p.y.push_back(r.pdet_cmh2o(i));
  }
  add_if_any(std::move(q), t);
  add_if_any(std::move(p), t);
}

// Qmax and PdetQmax of a recording with flow (and Pdet), and with time its flow time.
void add_ics_readouts(const RecordingAnalysis& m, CalibrationTargets& t) {
  const auto add = [&t](const char* name, Quantity q, double scale, std::optional<double> v) {
    if (!v) return;
    TargetSeries s = series(name, q, Abscissa::None, scale);
    s.x = {0.0};
    s.y = {*v};
    t.series.push_back(std::move(s));
  };
  if (!m.ics.qmax_ml_s || !(*m.ics.qmax_ml_s > 0.0)) return;
  add("maximum flow", Quantity::MaximumFlow, kQmaxScale, m.ics.qmax_ml_s);
  add("PdetQmax", Quantity::PdetAtMaximumFlow, kPdetQmaxScale, m.ics.pdet_qmax_cmh2o);
  if (m.recording.has_time())
    add("flow time", Quantity::FlowTime, kFlowTimeScale, m.ics.flow_time_s);
}

}  // namespace

std::string TargetSeries::unit() const {
  switch (quantity) {
    case Quantity::Pdet:
      return "cmH2O";
    case Quantity::Flow:
      return "ml/s";
    case Quantity::VoidedVolume:
      return "ml";
    case Quantity::OnsetDelay:
    case Quantity::FlowTime:
      return "s";
    case Quantity::MaximumFlow:
      return "ml/s";
    case Quantity::PdetAtMaximumFlow:
      return "cmH2O";
  }
  return "";
}

std::string TargetSeries::abscissa_name() const {
  switch (abscissa) {
    case Abscissa::BladderVolume:
      return "bladder volume (ml)";
    case Abscissa::TimeSinceFlowOnset:
      return "time since the onset of flow (s)";
    case Abscissa::VoidedVolume:
      return "voided volume (ml)";
    case Abscissa::None:
      break;
  }
  return quantity == Quantity::OnsetDelay ? "from the end of filling" : "end of voiding";
}

std::size_t CalibrationTargets::size() const {
  std::size_t n = 0;
  for (const auto& s : series) n += s.x.size();
  return n;
}

std::size_t Evaluation::compared_count() const {
  return static_cast<std::size_t>(std::count(compared.begin(), compared.end(), true));
}

CalibrationTargets filling_targets(const RecordingAnalysis& m, double lo_ml, double hi_ml) {
  CalibrationTargets t;
  TargetSeries s = series("filling Pdet", Quantity::Pdet, Abscissa::BladderVolume, kPressureScale);
  for (std::size_t i = 0; i < m.filling.x.size(); ++i) {
    if (m.filling.x[i] < lo_ml - 1e-9 || m.filling.x[i] > hi_ml + 1e-9) continue;
    s.x.push_back(m.filling.x[i]);
    s.y.push_back(m.filling.y[i]);
  }
  add_if_any(std::move(s), t);
  t.capacity_ml = hi_ml;
  return t;
}

bool add_voiding_targets(const RecordingAnalysis& m, CalibrationTargets& t) {
  const Recording& r = m.recording;
  if (!m.ics.voided_ml || *m.ics.voided_ml <= 0) return false;
  const std::size_t before = t.series.size();
  if (m.ics.voiding_start_s && r.has_time())
    add_timed_voiding(m, t);
  else
    add_volume_voiding(m, t);
  TargetSeries v = series("voided volume", Quantity::VoidedVolume, Abscissa::None, kVoidedScale);
  v.x = {0.0};
  v.y = {*m.ics.voided_ml};
  t.series.push_back(std::move(v));
  if (m.ics.voiding_start_s && r.has_time()) {
    TargetSeries d = series("onset of flow", Quantity::OnsetDelay, Abscissa::None, kOnsetScale);
    d.x = {0.0};
    d.y = {*m.ics.voiding_start_s - r.time_s[m.ics.capacity_row]};
    t.series.push_back(std::move(d));
  }
  add_ics_readouts(m, t);
  t.voiding = t.series.size() > before;
  if (m.ics.capacity_ml) t.capacity_ml = *m.ics.capacity_ml;
  return t.voiding;
}

std::vector<double> simulated_values(const TargetSeries& s, const ModelRun& run) {
  const SeriesValues v = series_values(s, simulated_curves(run.recording), run);
  return v.failure.empty() ? v.y : std::vector<double>();
}

Evaluation evaluate(const CalibrationTargets& t, const ModelRun& run) {
  Evaluation e;
  const std::size_t n = t.size();
  e.residuals = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(n), kFailedResidual);
  e.compared.assign(n, true);
  const SimulatedCurves curves = simulated_curves(run.recording);
  std::size_t row = 0;
  for (const auto& s : t.series) {
    const SeriesValues v = series_values(s, curves, run);
    if (!v.failure.empty()) {
      e.failed = true;
      e.failure = s.name + ": " + v.failure;
      e.residuals.setConstant(kFailedResidual);
      e.compared.assign(n, true);
      return e;
    }
    for (std::size_t i = 0; i < s.x.size(); ++i, ++row) {
      const double r = (v.y[i] - s.y[i]) / s.scale;
      e.compared[row] = std::isfinite(r);
      e.residuals[static_cast<Eigen::Index>(row)] = std::isfinite(r) ? r : 0.0;
    }
  }
  return e;
}

}  // namespace vesica::compare
