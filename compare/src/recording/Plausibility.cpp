#include "vesica/compare/recording/Plausibility.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "vesica/core/Error.h"

namespace vesica::compare {
namespace {

std::string number(double v) {
  return fmt::format("{:.4g}", v);
}

// The q-quantile of |values| (finite ones); 0 without any.
double abs_quantile(const std::vector<double>& values, double q) {
  std::vector<double> a;
  a.reserve(values.size());
  for (double v : values)
    if (std::isfinite(v)) a.push_back(std::abs(v));
  if (a.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(a.size() - 1));
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k), a.end());
  return a[k];
}

std::size_t row_of_max(const std::vector<double>& v) {
  return static_cast<std::size_t>(std::max_element(v.begin(), v.end()) - v.begin());
}

[[noreturn]] void refuse(const Recording& r, const std::string& rule, const std::string& what,
                         const std::string& hint) {
  fail(r.source, what + " (plausibility rule " + rule + ")", hint);
}

// pressure-in-pa: no bladder or abdomen holds hundreds of cmH2O for long.
void check_pressure_scale(const Recording& r, const PlausibilityLimits& l) {
  const std::pair<const char*, const std::vector<double>*> channels[] = {
      {"Pves", &r.pves_cmh2o}, {"Pabd", &r.pabd_cmh2o}, {"Pdet", &r.pdet_recorded_cmh2o}};
  for (const auto& [name, values] : channels) {
    if (values->empty()) continue;
    const double p95 = abs_quantile(*values, 0.95), top = abs_quantile(*values, 1.0);
    if (p95 > l.max_pressure_p95_cmh2o || top > l.max_pressure_cmh2o)
      refuse(r, "pressure-in-pa",
             std::string(name) + " reaches " + number(top) + " cmH2O (95 % of rows below " +
                 number(p95) + "): no bladder holds that",
             "pressures in Pa or kPa? name the unit: pves_pa, pves_kpa or --pressure-unit");
  }
  if (!r.pves_cmh2o.empty()) {
    const double top = *std::max_element(r.pves_cmh2o.begin(), r.pves_cmh2o.end());
    if (top < l.min_pves_max_cmh2o)
      refuse(r, "pressure-in-kpa",
             "Pves never exceeds " + number(top) +
                 " cmH2O over the whole study: the abdomen "
                 "alone gives more",
             "pressures in kPa? name the unit: pves_kpa or --pressure-unit kpa");
  }
}

// flow-in-ml-min: the fastest urinary flows are a few tens of ml/s.
void check_flow_scale(const Recording& r, const PlausibilityLimits& l,
                      std::vector<PlausibilityWarning>& warnings) {
  if (r.flow_ml_s.empty()) return;
  const std::size_t i = row_of_max(r.flow_ml_s);
  const double qmax = r.flow_ml_s[i];
  const std::string where = " at line " + std::to_string(r.line.at(i));
  if (qmax > l.max_qmax_ml_s)
    refuse(r, "flow-in-ml-min", "flow reaches " + number(qmax) + " ml/s" + where,
           "flow in ml/min? name the unit: flow_ml_min");
  if (qmax > l.high_qmax_ml_s)
    warnings.push_back({"flow-in-ml-min", "flow reaches " + number(qmax) + " ml/s" + where +
                                              ", above the flows reported in adults (" +
                                              number(l.high_qmax_ml_s) + " ml/s)"});
}

// negative-volume: a flowmeter or pump never takes urine back.
void check_volume_signs(const Recording& r, const PlausibilityLimits& l) {
  const std::pair<const char*, const std::vector<double>*> channels[] = {
      {"voided", &r.voided_ml}, {"infused", &r.infused_ml}};
  for (const auto& [name, values] : channels)
    for (std::size_t i = 0; i < values->size(); ++i)
      if ((*values)[i] < l.min_volume_ml)
        refuse(r, "negative-volume",
               std::string("the ") + name + " volume is " + number((*values)[i]) + " ml at line " +
                   std::to_string(r.line.at(i)),
               "a cumulative volume starts at 0 and never falls below it");
}

// voided-exceeds-infused: urine made during a study is tens of ml, not a multiple.
void check_voided_against_infused(const Recording& r, const PlausibilityLimits& l,
                                  std::vector<PlausibilityWarning>& warnings) {
  if (r.voided_ml.empty() || r.infused_ml.empty()) return;
  const double voided = *std::max_element(r.voided_ml.begin(), r.voided_ml.end());
  const double infused = *std::max_element(r.infused_ml.begin(), r.infused_ml.end());
  const std::string numbers =
      "voided " + number(voided) + " ml against " + number(infused) + " ml infused";
  if (voided > l.voided_over_infused_factor * infused + l.voided_over_infused_ml)
    refuse(r, "voided-exceeds-infused", numbers,
           "is the voided column in ml (not cl or l), and is it this study's?");
  if (voided > infused + l.excess_voided_ml)
    warnings.push_back({"voided-exceeds-infused",
                        numbers + ": urine made during the study, or a bladder not empty at "
                                  "the start; PVR is taken as 0"});
}

// flow-voided-mismatch: the flow's integral is the voided volume.
void check_flow_against_voided(const Recording& r, const PlausibilityLimits& l,
                               std::vector<PlausibilityWarning>& warnings) {
  if (r.flow_ml_s.empty() || r.voided_ml.empty() || r.time_s.empty()) return;
  double integral = 0;
  for (std::size_t i = 1; i < r.rows(); ++i)
    integral += 0.5 * (r.flow_ml_s[i] + r.flow_ml_s[i - 1]) * (r.time_s[i] - r.time_s[i - 1]);
  const double voided = r.voided_ml.back() - r.voided_ml.front();
  if (voided <= 0 || integral <= 0) return;
  const double ratio = integral / voided;
  if (ratio > l.flow_voided_ratio || ratio < 1.0 / l.flow_voided_ratio)
    warnings.push_back({"flow-voided-mismatch", "the flow integrates to " + number(integral) +
                                                    " ml, the voided volume "
                                                    "rises by " +
                                                    number(voided) +
                                                    " ml: a unit of one of them is wrong"});
}

}  // namespace

std::vector<PlausibilityWarning> check_plausibility(const Recording& r,
                                                    const PlausibilityLimits& limits) {
  std::vector<PlausibilityWarning> warnings;
  check_pressure_scale(r, limits);
  check_volume_signs(r, limits);
  check_flow_scale(r, limits, warnings);
  check_voided_against_infused(r, limits, warnings);
  check_flow_against_voided(r, limits, warnings);
  return warnings;
}

std::vector<PlausibilityWarning> check_compliance(double compliance,
                                                  const PlausibilityLimits& limits) {
  if (!(compliance > limits.max_compliance_ml_per_cmh2o)) return {};
  return {{"compliance",
           "a compliance of " + number(compliance) + " ml/cmH2O, beyond what bladders show (" +
               number(limits.max_compliance_ml_per_cmh2o) + "): pressures in kPa labelled cmH2O?"}};
}

}  // namespace vesica::compare
