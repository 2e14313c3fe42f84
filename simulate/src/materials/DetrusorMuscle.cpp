// Active detrusor stress with length–tension and Hill force–velocity (docs/physics.md §2.6).
#include "materials/DetrusorMuscle.h"

#include <cmath>

namespace vesica::simulate {

HillFactor hill_factor(const MuscleParameters& m, double v) {
  const double vmax = m.hill_vmax, k = m.hill_a;
  if (v >= vmax) return {0.0, 0.0};
  if (v >= 0.0) {
    const double num = 1.0 - v / vmax, den = 1.0 + v / (k * vmax);
    return {num / den, (-1.0 / vmax * den - num / (k * vmax)) / (den * den)};
  }
  const double e = m.eccentric_max;
  const double c = (e - 1.0) * k * vmax / (1.0 + k);
  const double q = 1.0 - v / c;
  return {e - (e - 1.0) / q, -(e - 1.0) / (c * q * q)};
}

void DetrusorMuscle::add_stress(const Eigen::Matrix3d& C, const MaterialPoint& point,
                                const double* history_old, double* history_new, Eigen::Matrix3d& S,
                                Voigt6& D) const {
  const double T = m_.tone + point.activation * m_.contractility;
  for (int f = 0; f < 2; ++f) {
    const Eigen::Vector3d& a0 = point.fibers[f];
    const double lambda = std::sqrt(a0.dot(C * a0));
    const double lambda_old = 1.0 + history_old[2 * f];
    // Length–tension: a Gaussian about the optimal stretch.
    const double x = (lambda - m_.optimal_stretch) / m_.stretch_width;
    const double fl = std::exp(-x * x);
    const double dfl = -2.0 * x / m_.stretch_width * fl;
    // Force–velocity: backward Euler on the shortening rate; a step without time keeps the
    // committed factor (settling, and the outputs of a committed state).
    HillFactor fv{1.0 + history_old[2 * f + 1], 0.0};
    double dv_dlambda = 0.0;
    if (point.dt_s > 0.0) {
      const double v = -std::log(lambda / lambda_old) / point.dt_s;
      fv = hill_factor(m_, v);
      dv_dlambda = -1.0 / (lambda * point.dt_s);
    }
    history_new[2 * f] = lambda - 1.0;
    history_new[2 * f + 1] = fv.value - 1.0;
    if (T == 0.0) continue;
    // g = P_a / λ and its derivative with respect to I4 = λ².
    const double g = T * fl * fv.value / lambda;
    const double dg_dlambda =
        T * (dfl * fv.value + fl * fv.d_dv * dv_dlambda) / lambda - g / lambda;
    const double dg_dI4 = dg_dlambda / (2.0 * lambda);
    const Eigen::Matrix3d A = a0 * a0.transpose();
    S += g * A;
    D += 2.0 * dg_dI4 * outer(A, A);  // D = 2 dS/dC, dI4/dC = A
  }
}

}  // namespace vesica::simulate
