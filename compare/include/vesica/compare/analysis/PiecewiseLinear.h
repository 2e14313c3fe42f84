#pragma once
// A piecewise-linear function through samples (x, y), for putting a measured and a
// simulated curve on one grid. Samples are sorted by x; samples with equal x are averaged
// (a simulated hold at constant volume, repeated clinical readings); non-finite samples are
// dropped.
#include <vector>

namespace vesica::compare {

class PiecewiseLinear {
 public:
  PiecewiseLinear(const std::vector<double>& x, const std::vector<double>& y);
  bool empty() const { return x_.empty(); }
  double x_min() const { return x_.front(); }
  double x_max() const { return x_.back(); }
  // Linear between samples, constant beyond the ends; NaN when there are no samples.
  double operator()(double x) const;

 private:
  std::vector<double> x_, y_;
};

// lo, lo + step, ..., with hi as the last point (the last step may be shorter).
std::vector<double> grid(double lo, double hi, double step);

}  // namespace vesica::compare
