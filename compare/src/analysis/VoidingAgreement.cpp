#include "vesica/compare/analysis/VoidingAgreement.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "vesica/compare/analysis/ModelComparison.h"
#include "vesica/compare/analysis/PiecewiseLinear.h"

namespace vesica::compare {
namespace {

nlohmann::json value(const Maybe& m) {
  return m ? nlohmann::json(*m) : nlohmann::json();
}

nlohmann::json to_json(const MeasuredAndSimulated& m) {
  return {{"measured", value(m.measured)}, {"simulated", value(m.simulated)}};
}

nlohmann::json to_json(const Curve& c) {
  return {{"time_s", c.x}, {"flow_ml_s", c.y}};
}

// The flow curve zero outside its samples.
double flow_at(const Curve& c, const PiecewiseLinear& f, double t) {
  if (c.x.empty() || t < c.x.front() || t > c.x.back()) return 0.0;
  return f(t);
}

}  // namespace

Maybe aligned_flow_correlation(const Curve& a, const Curve& b, double step_s) {
  if (a.x.size() < 2 || b.x.size() < 2) return std::nullopt;
  const PiecewiseLinear fa(a.x, a.y), fb(b.x, b.y);
  const double end = std::max(a.x.back(), b.x.back());
  double n = 0, ma = 0, mb = 0;
  const std::vector<double> t = grid(0.0, end, step_s);
  for (double s : t) {
    ma += flow_at(a, fa, s);
    mb += flow_at(b, fb, s);
    n += 1;
  }
  ma /= n;
  mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (double s : t) {
    const double da = flow_at(a, fa, s) - ma, db = flow_at(b, fb, s) - mb;
    sab += da * db;
    saa += da * da;
    sbb += db * db;
  }
  if (saa <= 0 || sbb <= 0) return std::nullopt;
  return sab / std::sqrt(saa * sbb);
}

VoidingAgreement voiding_agreement(const RecordingAnalysis& measured, const Recording& simulated) {
  VoidingAgreement v;
  const IcsParameters& m = measured.ics;
  const IcsParameters s = compute_ics(simulated, {});
  v.qmax_ml_s = {m.qmax_ml_s, s.qmax_ml_s};
  v.flow_time_s = {m.flow_time_s, s.flow_time_s};
  v.voided_ml = {m.voided_ml, s.voided_ml};
  v.pdet_qmax_cmh2o = {m.pdet_qmax_cmh2o, s.pdet_qmax_cmh2o};
  if (!measured.recording.has_time()) return v;
  v.measured_flow_ml_s = voiding_curves(measured.recording, m).flow_ml_s;
  v.simulated_flow_ml_s = voiding_curves(simulated, s).flow_ml_s;
  v.flow_correlation = aligned_flow_correlation(v.measured_flow_ml_s, v.simulated_flow_ml_s);
  return v;
}

nlohmann::json to_json(const VoidingAgreement& v) {
  return {{"qmax_ml_s", to_json(v.qmax_ml_s)},
          {"flow_time_s", to_json(v.flow_time_s)},
          {"voided_ml", to_json(v.voided_ml)},
          {"pdet_qmax_cmh2o", to_json(v.pdet_qmax_cmh2o)},
          {"flow_correlation_aligned_onsets", value(v.flow_correlation)},
          {"measured_flow", to_json(v.measured_flow_ml_s)},
          {"simulated_flow", to_json(v.simulated_flow_ml_s)}};
}

}  // namespace vesica::compare
