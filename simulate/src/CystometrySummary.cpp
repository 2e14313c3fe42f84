#include "vesica/simulate/CystometrySummary.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "vesica/core/Units.h"

namespace vesica::simulate {

void summarize_history(const std::vector<HistoryRow>& h, std::size_t capacity_index,
                       nlohmann::json& s) {
  if (h.empty()) return;
  const HistoryRow& first = h.front();
  const HistoryRow& cap = h[std::min(capacity_index, h.size() - 1)];
  s["capacity_ml"] = cap.volume_ml;
  s["pdet_at_capacity_cmh2o"] = cap.pdet_cmh2o;
  s["pves_at_capacity_cmh2o"] = cap.pves_cmh2o;
  const double dp = cap.pdet_cmh2o - first.pdet_cmh2o;
  s["compliance_ml_per_cmh2o"] =
      dp > 0.0 ? nlohmann::json((cap.volume_ml - first.volume_ml) / dp) : nlohmann::json();
  double qmax = 0.0, pdet_qmax = 0.0, t_qmax = 0.0, pdet_max = 0.0, flow_time = 0.0;
  for (std::size_t i = capacity_index + 1; i < h.size(); ++i) {
    if (h[i].flow_ml_s > qmax) {
      qmax = h[i].flow_ml_s;
      pdet_qmax = h[i].pdet_cmh2o;
      t_qmax = h[i].time_s - cap.time_s;
    }
    pdet_max = std::max(pdet_max, h[i].pdet_cmh2o);
    if (h[i].flow_ml_s > 0.0) flow_time += h[i].time_s - h[i - 1].time_s;
  }
  const HistoryRow& last = h.back();
  const bool voided = h.size() > capacity_index + 1;
  s["voided_ml"] = last.voided_ml;
  s["qmax_ml_s"] = qmax;
  if (voided) {
    s["pvr_ml"] = last.volume_ml;
    s["pdet_at_qmax_cmh2o"] = pdet_qmax;
    s["pdet_max_voiding_cmh2o"] = pdet_max;
    s["time_to_qmax_s"] = t_qmax;
    s["flow_time_s"] = flow_time;
    s["voiding_time_s"] = last.time_s - cap.time_s;
    s["qave_ml_s"] = flow_time > 0.0 ? last.voided_ml / flow_time : 0.0;
    const double total = last.voided_ml + last.volume_ml;
    s["voiding_efficiency"] = total > 0.0 ? last.voided_ml / total : 0.0;
    s["booi"] = pdet_qmax - 2.0 * qmax;
    s["bci"] = pdet_qmax + 5.0 * qmax;
  }
}

std::string step_failure_text(double t_s, double volume_m3, const std::string& reason) {
  std::ostringstream s;
  s.precision(6);
  s << "step failed at t = " << t_s << " s, V = " << units::ml_from_m3(volume_m3)
    << " ml: " << reason;
  return s.str();
}

std::string no_voiding_note(const CystometryProtocol& protocol, double pves_pa) {
  if (protocol.detrusor_kpa > 0.0 || protocol.straining_kpa > 0.0 ||
      units::cmh2o_from_pa(pves_pa) >= protocol.p_open_cmh2o)
    return "";
  return "no voiding: Pves stays below the opening pressure without detrusor_kpa or "
         "straining_kpa";
}

std::pair<std::string, double> protocol_progress(const HistoryRow& row,
                                                 const CystometryProtocol& protocol, bool voiding) {
  char step[64];
  if (!voiding) {
    const double span = protocol.capacity_ml - protocol.start_ml;
    const double done = span > 0.0 ? std::clamp(row.infused_ml / span, 0.0, 1.0) : 1.0;
    std::snprintf(step, sizeof step, "filling %.0f ml", row.volume_ml);
    return {step, 0.8 * done};
  }
  const double total = row.voided_ml + row.volume_ml;
  std::snprintf(step, sizeof step, "voiding %.0f ml", row.volume_ml);
  return {step, 0.8 + 0.2 * (total > 0.0 ? row.voided_ml / total : 1.0)};
}

}  // namespace vesica::simulate
