#include "vesica/simulate/protocol/CystometrySummary.h"

#include <algorithm>

#include <nlohmann/json.hpp>

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

}  // namespace vesica::simulate
