#include "vesica/compare/analysis/PiecewiseLinear.h"

#include <algorithm>
#include <cmath>

namespace vesica::compare {

PiecewiseLinear::PiecewiseLinear(const std::vector<double>& x, const std::vector<double>& y) {
  // non-finite samples (a diverged simulation step) carry no information
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (std::isfinite(x[i]) && std::isfinite(y[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return x[a] < x[b]; });
  std::size_t count = 0;
  for (std::size_t i : order) {
    if (!x_.empty() && x[i] == x_.back()) {
      ++count;
      y_.back() += (y[i] - y_.back()) / count;  // running mean of equal-x samples
      continue;
    }
    x_.push_back(x[i]);
    y_.push_back(y[i]);
    count = 1;
  }
}

double PiecewiseLinear::operator()(double x) const {
  if (x_.empty()) return std::nan("");
  if (x <= x_.front()) return y_.front();
  if (x >= x_.back()) return y_.back();
  const auto it = std::upper_bound(x_.begin(), x_.end(), x);
  const std::size_t i = static_cast<std::size_t>(it - x_.begin());
  const double t = (x - x_[i - 1]) / (x_[i] - x_[i - 1]);
  return y_[i - 1] + t * (y_[i] - y_[i - 1]);
}

std::vector<double> grid(double lo, double hi, double step) {
  std::vector<double> g;
  if (!(hi >= lo) || step <= 0) return g;
  for (double v = lo; v < hi - 1e-9 * step; v += step) g.push_back(v);
  g.push_back(hi);
  return g;
}

}  // namespace vesica::compare
