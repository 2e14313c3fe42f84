#include "protocol/ActivationCurve.h"

#include <cmath>

namespace vesica::simulate {
namespace {

// 1 − exp(−t/τ), a step for τ = 0.
double first_order_rise(double t, double tau) {
  return tau > 0.0 ? -std::expm1(-t / tau) : 1.0;
}

}  // namespace

double ActivationCurve::at(double t_since_start) const {
  const double t = t_since_start - delay_s;
  if (t <= 0.0) return 0.0;
  if (t <= plateau_s) return first_order_rise(t, onset_s);
  const double held = first_order_rise(plateau_s, onset_s);
  return fade_s > 0.0 ? held * std::exp(-(t - plateau_s) / fade_s) : 0.0;
}

}  // namespace vesica::simulate
