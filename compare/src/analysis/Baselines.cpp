#include "vesica/compare/analysis/Baselines.h"

#include <algorithm>
#include <cmath>

namespace vesica::compare {

BaselineRmse baseline_rmse(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(y.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    mx += x[i] / n;
    my += y[i] / n;
  }
  // Centred sums: the line's slope is sxy/sxx, its residual sum syy - sxy²/sxx.
  double sxx = 0, sxy = 0, syy = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  BaselineRmse b;
  b.constant = std::sqrt(syy / n);
  const double line_sum = sxx > 0 ? std::max(0.0, syy - sxy * sxy / sxx) : syy;
  b.line = std::sqrt(line_sum / n);
  return b;
}

}  // namespace vesica::compare
