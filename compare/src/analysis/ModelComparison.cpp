#include "vesica/compare/analysis/ModelComparison.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "vesica/compare/analysis/PiecewiseLinear.h"

namespace vesica::compare {
namespace {

nlohmann::json value(const std::optional<double>& m) {
  return m ? nlohmann::json(*m) : nlohmann::json();
}

nlohmann::json to_json(const CurveDifference& d, const char* unit) {
  const std::string u = unit;
  return {{"range_lo", d.lo},
          {"range_hi", d.hi},
          {"points", d.grid.size()},
          {"rmse_" + u, value(d.rmse)},
          {"max_abs_error_" + u, value(d.max_abs_error)}};
}

}  // namespace

std::vector<double> CurveDifference::residuals() const {
  std::vector<double> r(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) r[i] = simulated[i] - measured[i];
  return r;
}

CurveDifference compare_curves(const Curve& measured, const Curve& simulated, double lo_limit,
                               double hi_limit, double step) {
  CurveDifference d;
  if (measured.x.size() < 2 || simulated.x.size() < 2) return d;
  const PiecewiseLinear m(measured.x, measured.y), s(simulated.x, simulated.y);
  d.lo = std::max({m.x_min(), s.x_min(), lo_limit});
  d.hi = std::min({m.x_max(), s.x_max(), hi_limit});
  if (!(d.hi > d.lo)) return d;
  d.grid = grid(d.lo, d.hi, step);
  double sum = 0, worst = 0;
  for (double x : d.grid) {
    d.measured.push_back(m(x));
    d.simulated.push_back(s(x));
    const double e = d.simulated.back() - d.measured.back();
    sum += e * e;
    worst = std::max(worst, std::abs(e));
  }
  d.rmse = std::sqrt(sum / d.grid.size());
  d.max_abs_error = worst;
  return d;
}

CurveDifference compare_filling(const Curve& measured, const Curve& simulated,
                                const ComparisonOptions& o) {
  const double lo = o.volume_range_ml ? o.volume_range_ml->first : -HUGE_VAL;
  const double hi = o.volume_range_ml ? o.volume_range_ml->second : HUGE_VAL;
  return compare_curves(measured, simulated, lo, hi, o.volume_step_ml);
}

VoidingCurves voiding_curves(const Recording& r, const IcsParameters& p) {
  VoidingCurves c;
  if (!p.voiding_start_s) return c;
  const auto voided = r.voided_or_integrated_ml();
  for (std::size_t i = 0; i < r.rows(); ++i) {
    if (r.time_s[i] < *p.voiding_start_s) continue;
    const double t = r.time_s[i] - *p.voiding_start_s;
    c.voided_ml.x.push_back(t);
    c.voided_ml.y.push_back(voided[i]);
    c.flow_ml_s.x.push_back(t);
    c.flow_ml_s.y.push_back(r.flow_ml_s[i]);
  }
  return c;
}

nlohmann::json compare_models(const Recording& measured, const IcsParameters& mi, const Curve& mf,
                              const Recording& simulated, const IcsParameters& si, const Curve& sf,
                              const ComparisonOptions& o) {
  nlohmann::json out;
  out["filling_pdet"] = to_json(compare_filling(mf, sf, o), "cmh2o");
  out["filling_pdet"]["volume_unit"] = "ml";
  // simulated - measured for every parameter both recordings give
  const auto mj = to_json(mi), sj = to_json(si);
  nlohmann::json diff = nlohmann::json::object();
  for (auto it = mj.begin(); it != mj.end(); ++it) {
    if (it.key() == "voiding_start_s" || !it.value().is_number() || !sj.contains(it.key()) ||
        !sj[it.key()].is_number())
      continue;
    diff[it.key()] = sj[it.key()].get<double>() - it.value().get<double>();
  }
  out["parameter_difference_simulated_minus_measured"] = diff;
  const auto mv = voiding_curves(measured, mi), sv = voiding_curves(simulated, si);
  out["voiding_voided_volume"] =
      to_json(compare_curves(mv.voided_ml, sv.voided_ml, 0, HUGE_VAL, o.time_step_s), "ml");
  out["voiding_voided_volume"]["time_unit"] = "s since onset of flow";
  out["voiding_flow"] =
      to_json(compare_curves(mv.flow_ml_s, sv.flow_ml_s, 0, HUGE_VAL, o.time_step_s), "ml_s");
  out["voiding_flow"]["time_unit"] = "s since onset of flow";
  return out;
}

}  // namespace vesica::compare
