#include "vesica/io/Recording.h"

#include <algorithm>

namespace vesica::io {

std::size_t Recording::rows() const {
  return std::max({time_s.size(), pves_cmh2o.size(), pabd_cmh2o.size(), pdet_recorded_cmh2o.size(),
                   flow_ml_s.size(), voided_ml.size(), infused_ml.size(), volume_ml.size()});
}

bool Recording::has_pdet() const {
  return !pdet_recorded_cmh2o.empty() || (!pves_cmh2o.empty() && !pabd_cmh2o.empty());
}

double Recording::pdet_cmh2o(std::size_t i) const {
  if (!pdet_recorded_cmh2o.empty()) return pdet_recorded_cmh2o[i];
  return pves_cmh2o[i] - pabd_cmh2o[i];
}

bool Recording::has_volume() const {
  return !volume_ml.empty() || !infused_ml.empty();
}

double Recording::bladder_volume_ml(std::size_t i) const {
  if (!volume_ml.empty()) return volume_ml[i];
  const double voided = voided_ml.empty() ? 0.0 : voided_ml[i];
  const double infused = infused_ml.empty() ? 0.0 : infused_ml[i];
  return start_volume_ml + infused - voided;
}

std::vector<double> Recording::voided_or_integrated_ml() const {
  if (!voided_ml.empty()) return voided_ml;
  std::vector<double> v(rows(), 0.0);
  if (flow_ml_s.empty() || time_s.empty()) return v;
  for (std::size_t i = 1; i < rows(); ++i)
    v[i] = v[i - 1] + 0.5 * (flow_ml_s[i] + flow_ml_s[i - 1]) * (time_s[i] - time_s[i - 1]);
  return v;
}

}  // namespace vesica::io
