#include "vesica/compare/analysis/IcsParameters.h"

#include <algorithm>
#include <cctype>
#include <cmath>

#include <nlohmann/json.hpp>

#include "vesica/core/Units.h"

namespace vesica::compare {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::size_t first_unflagged(const std::vector<bool>& flagged) {
  for (std::size_t i = 0; i < flagged.size(); ++i)
    if (!flagged[i]) return i;
  return 0;
}

// Capacity: the first row at which the bladder volume reaches its maximum (end of filling).
// A simulated bladder held at capacity (an isovolumetric contraction) keeps its volume only
// to the solver's tolerance: a rise of less than kSameVolumeMl is the same volume, not a
// later capacity.
std::size_t capacity_row(const Recording& r) {
  constexpr double kSameVolumeMl = 1e-6;
  std::size_t best = 0;
  for (std::size_t i = 1; i < r.rows(); ++i)
    if (r.bladder_volume_ml(i) > r.bladder_volume_ml(best) + kSameVolumeMl) best = i;
  return best;
}

// The nearest unflagged row at or before `row`, for pressures read at a given moment.
std::size_t unflagged_at_or_before(std::size_t row, const std::vector<bool>& flagged) {
  for (std::size_t i = row + 1; i-- > 0;)
    if (!flagged[i]) return i;
  return row;
}

void fill_desires(const Recording& r, IcsParameters& p) {
  if (r.event.empty()) return;
  for (std::size_t i = 0; i < r.rows(); ++i) {
    const std::string e = lower(r.event[i]);
    const double v = r.bladder_volume_ml(i);
    if (!p.first_desire_ml && (e.find("first desire") != std::string::npos ||
                               e.find("first sensation") != std::string::npos))
      p.first_desire_ml = v;
    if (!p.normal_desire_ml && e.find("normal desire") != std::string::npos) p.normal_desire_ml = v;
    if (!p.strong_desire_ml && e.find("strong desire") != std::string::npos) p.strong_desire_ml = v;
  }
}

void fill_filling(const Recording& r, const std::vector<bool>& flagged, IcsParameters& p) {
  p.filling_start_row = first_unflagged(flagged);
  p.capacity_row = capacity_row(r);
  const std::size_t s = p.filling_start_row;
  const std::size_t c = unflagged_at_or_before(p.capacity_row, flagged);
  p.volume_start_ml = r.bladder_volume_ml(s);
  p.capacity_ml = r.bladder_volume_ml(p.capacity_row);
  if (!r.has_pdet()) return;
  p.pdet_start_cmh2o = r.pdet_cmh2o(s);
  p.pdet_capacity_cmh2o = r.pdet_cmh2o(c);
  const double dp = *p.pdet_capacity_cmh2o - *p.pdet_start_cmh2o;
  // A flat or falling Pdet has no finite compliance; report none rather than infinity.
  if (dp > 1e-9) p.compliance_ml_per_cmh2o = (*p.capacity_ml - *p.volume_start_ml) / dp;
}

// Flow is a linear interpolant of the samples; it is positive on every interval with a
// positive end, so flow time is the total length of those intervals.
void fill_flow_times(const Recording& r, IcsParameters& p) {
  const auto& q = r.flow_ml_s;
  double flow_time = 0.0;
  Maybe start, end;
  for (std::size_t i = 0; i + 1 < r.rows(); ++i) {
    if (q[i] <= 0.0 && q[i + 1] <= 0.0) continue;
    flow_time += r.time_s[i + 1] - r.time_s[i];
    if (!start) start = r.time_s[i];
    end = r.time_s[i + 1];
  }
  if (!start) return;
  p.flow_time_s = flow_time;
  p.voiding_time_s = *end - *start;
  p.voiding_start_s = start;
}

// A row during flow: positive flow, or (a table without flow) a rise of the voided volume.
bool flowing(const Recording& r, const std::vector<double>& voided, std::size_t i) {
  if (r.has_flow()) return r.flow_ml_s[i] > 0.0;
  return i > 0 && voided[i] > voided[i - 1];
}

// Opening, closing and maximum Pdet: first/last unflagged rows with flow; maximum: every
// unflagged row from the onset to the end of flow, even where the flow momentarily reads zero.
void fill_voiding_pressures(const Recording& r, const std::vector<bool>& flagged,
                            const std::vector<double>& voided, IcsParameters& p) {
  Maybe first, last, highest;
  std::size_t lo = r.rows(), hi = 0;
  for (std::size_t i = 0; i < r.rows(); ++i) {
    if (!flowing(r, voided, i)) continue;
    lo = std::min(lo, i);
    hi = i;
    if (flagged[i]) continue;
    if (!first) first = r.pdet_cmh2o(i);
    last = r.pdet_cmh2o(i);
  }
  for (std::size_t i = lo; i <= hi && i < r.rows(); ++i)
    if (!flagged[i]) highest = highest ? std::max(*highest, r.pdet_cmh2o(i)) : r.pdet_cmh2o(i);
  p.pdet_opening_cmh2o = first;
  p.pdet_closing_cmh2o = last;
  p.pdet_max_voiding_cmh2o = highest;
}

void fill_voiding(const Recording& r, const std::vector<bool>& flagged, IcsParameters& p) {
  if (!r.has_flow() && r.voided_ml.empty()) return;
  const auto voided = r.voided_or_integrated_ml();
  p.voided_ml = voided.back();
  // Without a voided volume (flow, but no time to integrate it) the bladder volume never
  // falls: PVR and efficiency are unknown, not the whole capacity and 0.
  if (!r.voided_ml.empty() || !r.volume_ml.empty()) {
    p.pvr_ml = std::max(0.0, r.bladder_volume_ml(r.rows() - 1));
    if (*p.voided_ml + *p.pvr_ml > 0)
      p.voiding_efficiency = *p.voided_ml / (*p.voided_ml + *p.pvr_ml);
  } else {
    p.notes.push_back(
        "no voided volume (flow without time): PVR and voiding efficiency are "
        "left out");
  }
  if (!r.has_time())
    p.notes.push_back(
        "no time column: flow time, voiding time, Qave and time to Qmax "
        "need one and are left out");
  if (r.has_pdet()) fill_voiding_pressures(r, flagged, voided, p);
  if (!r.has_flow()) return;
  const auto& q = r.flow_ml_s;
  const std::size_t imax = std::max_element(q.begin(), q.end()) - q.begin();
  if (q[imax] <= 0.0) return;
  p.qmax_ml_s = q[imax];
  if (r.has_time()) {
    fill_flow_times(r, p);
    if (p.flow_time_s && *p.flow_time_s > 0) p.qave_ml_s = *p.voided_ml / *p.flow_time_s;
    if (p.voiding_start_s) p.time_to_qmax_s = r.time_s[imax] - *p.voiding_start_s;
  }
  if (!r.has_pdet()) return;
  p.pdet_qmax_cmh2o = r.pdet_cmh2o(imax);
  p.booi = *p.pdet_qmax_cmh2o - 2.0 * *p.qmax_ml_s;
  p.bci = *p.pdet_qmax_cmh2o + 5.0 * *p.qmax_ml_s;
  p.booi_class = booi_class(*p.booi);
  p.bci_class = bci_class(*p.bci);
}

// The infusion rate: the least-squares slope of the bladder volume against time over the
// filling rows (start to capacity); none without time.
void fill_rate(const Recording& r, IcsParameters& p) {
  if (!r.has_time() || p.capacity_row <= p.filling_start_row) return;
  double n = 0, mt = 0, mv = 0;
  for (std::size_t i = p.filling_start_row; i <= p.capacity_row; ++i, n += 1) {
    mt += r.time_s[i];
    mv += r.bladder_volume_ml(i);
  }
  mt /= n;
  mv /= n;
  double stt = 0, stv = 0;
  for (std::size_t i = p.filling_start_row; i <= p.capacity_row; ++i) {
    stt += (r.time_s[i] - mt) * (r.time_s[i] - mt);
    stv += (r.time_s[i] - mt) * (r.bladder_volume_ml(i) - mv);
  }
  if (stt > 0 && stv > 0) p.fill_rate_ml_min = stv / stt * units::kSecondsPerMinute;
}

nlohmann::json value(const Maybe& m) {
  return m ? nlohmann::json(*m) : nlohmann::json();
}

}  // namespace

std::string booi_class(double booi) {
  if (booi > 40) return "obstructed";
  if (booi >= 20) return "equivocal";
  return "unobstructed";
}

std::string bci_class(double bci) {
  if (bci > 150) return "strong";
  if (bci >= 100) return "normal";
  return "weak";
}

IcsParameters compute_ics(const Recording& r, const std::vector<ArtefactFlag>& flags) {
  const auto flagged = flagged_rows(r, flags);
  IcsParameters p;
  fill_filling(r, flagged, p);
  fill_desires(r, p);
  fill_rate(r, p);
  fill_voiding(r, flagged, p);
  return p;
}

nlohmann::json to_json(const IcsParameters& p) {
  return {
      {"volume_start_ml", value(p.volume_start_ml)},
      {"pdet_start_cmh2o", value(p.pdet_start_cmh2o)},
      {"capacity_ml", value(p.capacity_ml)},
      {"pdet_capacity_cmh2o", value(p.pdet_capacity_cmh2o)},
      {"compliance_ml_per_cmh2o", value(p.compliance_ml_per_cmh2o)},
      {"first_desire_ml", value(p.first_desire_ml)},
      {"normal_desire_ml", value(p.normal_desire_ml)},
      {"strong_desire_ml", value(p.strong_desire_ml)},
      {"qmax_ml_s", value(p.qmax_ml_s)},
      {"qave_ml_s", value(p.qave_ml_s)},
      {"flow_time_s", value(p.flow_time_s)},
      {"voiding_time_s", value(p.voiding_time_s)},
      {"time_to_qmax_s", value(p.time_to_qmax_s)},
      {"voided_ml", value(p.voided_ml)},
      {"pvr_ml", value(p.pvr_ml)},
      {"voiding_efficiency", value(p.voiding_efficiency)},
      {"pdet_qmax_cmh2o", value(p.pdet_qmax_cmh2o)},
      {"pdet_opening_cmh2o", value(p.pdet_opening_cmh2o)},
      {"pdet_max_voiding_cmh2o", value(p.pdet_max_voiding_cmh2o)},
      {"pdet_closing_cmh2o", value(p.pdet_closing_cmh2o)},
      {"booi", value(p.booi)},
      {"booi_class", p.booi_class},
      {"bci", value(p.bci)},
      {"bci_class", p.bci_class},
      {"voiding_start_s", value(p.voiding_start_s)},
      {"fill_rate_ml_min", value(p.fill_rate_ml_min)},
      {"notes", p.notes},
  };
}

Curve filling_curve(const Recording& r, const IcsParameters& p, const std::vector<bool>& flagged) {
  Curve c;
  if (!r.has_pdet()) return c;
  for (std::size_t i = 0; i <= p.capacity_row && i < r.rows(); ++i) {
    if (flagged[i]) continue;
    c.x.push_back(r.bladder_volume_ml(i));
    c.y.push_back(r.pdet_cmh2o(i));
  }
  return c;
}

}  // namespace vesica::compare
