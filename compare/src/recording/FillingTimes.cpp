#include "vesica/compare/recording/FillingTimes.h"

#include <algorithm>

namespace vesica::compare {

FillingTimes filling_times(const Recording& r, const IcsParameters& p) {
  FillingTimes f;
  if (r.rows() == 0 || !r.has_time()) return f;  // a table without time has no clock
  f.start_s = r.time_s.front();
  if (r.infused_ml.empty()) return f;
  std::size_t first = 0;
  while (first < r.rows() && !(r.infused_ml[first] > 0.0)) ++first;
  const std::size_t capacity = p.capacity_row;
  if (first >= r.rows() || capacity <= first) return f;
  const double dt = r.time_s[capacity] - r.time_s[first];
  const double dv = r.infused_ml[capacity] - r.infused_ml[first];
  if (!(dt > 0.0) || !(dv > 0.0)) return f;
  const double rate_ml_s = dv / dt;
  f.mean_rate_ml_min = 60.0 * rate_ml_s;
  f.start_s = r.time_s[first] - r.infused_ml[first] / rate_ml_s;
  if (first > 0) f.start_s = std::max(f.start_s, r.time_s[first - 1]);
  return f;
}

}  // namespace vesica::compare
