#include "vesica/simulate/protocol/PressureTrace.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace vesica::simulate {

double PressureTrace::at(double t_s) const {
  if (t_s <= time_s.front()) return cmh2o.front();
  if (t_s >= time_s.back()) return cmh2o.back();
  const auto hi = static_cast<std::size_t>(std::upper_bound(time_s.begin(), time_s.end(), t_s) -
                                           time_s.begin());
  const std::size_t lo = hi - 1;
  const double w = (t_s - time_s[lo]) / (time_s[hi] - time_s[lo]);
  return (1.0 - w) * cmh2o[lo] + w * cmh2o[hi];
}

std::string PressureTrace::problem() const {
  if (time_s.size() != cmh2o.size()) return "needs one pressure per time";
  for (std::size_t i = 0; i < time_s.size(); ++i) {
    if (!std::isfinite(time_s[i]) || !std::isfinite(cmh2o[i])) return "has a non-finite reading";
    if (i > 0 && !(time_s[i] > time_s[i - 1])) return "needs strictly increasing times";
  }
  return "";
}

}  // namespace vesica::simulate
