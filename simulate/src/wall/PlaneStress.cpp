#include "wall/PlaneStress.h"

#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace vesica::simulate {
namespace {
constexpr int kPlane[3] = {0, 1, 3};  // Voigt positions of 11, 22, 12
constexpr int k33 = 2;

// What "small" is measured against for S33: the in-plane stress.
double in_plane_stress_scale(const Eigen::Matrix3d& S) {
  return std::abs(S(0, 0)) + std::abs(S(1, 1)) + std::abs(S(0, 1));
}
}  // namespace

// S33 is the small difference of volumetric and isochoric terms of size ≈ C33 dS33/dC33
// (≈ K): its round-off is a few ulps of that, far above 1e-13 of the in-plane stress of
// a nearly incompressible wall. Without this floor the iteration ran on until its step
// test stopped it, 7 material evaluations per call instead of 3.
bool plane_stress_converged(const Eigen::Matrix3d& S, const Voigt6& D, double c33,
                            double stress_scale) {
  if (stress_scale < 0.0) stress_scale = in_plane_stress_scale(S);
  const double round_off = 8.0 * DBL_EPSILON * 0.5 * std::abs(D(k33, k33)) * c33;
  return std::abs(S(k33, k33)) <= std::max(1e-13 * stress_scale, round_off);
}

// S33(C33) → -∞ as C33 → 0 (the volumetric term) and is positive for a large C33, so
// a root is bracketed; Newton steps are taken inside the bracket and replaced by
// bisection when they leave it (the Ogden term makes S33 non-monotonic far from the
// root, where a plain Newton iteration could run away).
PlaneStressState plane_stress(const Material& material, const Eigen::Matrix2d& C2,
                              const MaterialPoint& point, double J2_guess,
                              const double* history_old, double* history_new) {
  const double det2 = C2.determinant();
  if (!(det2 > 0.0)) throw std::runtime_error("plane stress: inverted element");
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  C.topLeftCorner<2, 2>() = C2;
  Eigen::Matrix3d S;
  Voigt6 D;
  auto S33 = [&](double c33) {
    C(2, 2) = c33;
    material.evaluate(C, point, history_old, history_new, S, D);
    return S(2, 2);
  };
  double c33 = (J2_guess > 0.0 ? J2_guess : 1.0) / det2;
  double f = S33(c33);
  // The scale of the first evaluation throughout: the test does not drift with the iterate.
  const double stress_scale = in_plane_stress_scale(S);
  auto converged = [&] { return plane_stress_converged(S, D, c33, stress_scale); };
  if (!converged()) {
    double lo = 0.0, hi = INFINITY;
    (f > 0.0 ? hi : lo) = c33;
    bool done = false;
    for (int it = 0; it < 200 && !done; ++it) {
      const double slope = 0.5 * D(k33, k33);  // dS33/dC33 (D = 2 dS/dC)
      double next = slope > 0.0 ? c33 - f / slope : NAN;
      if (!(next > lo && next < hi))
        next = std::isfinite(hi) ? (lo > 0.0 ? 0.5 * (lo + hi) : 0.5 * hi) : 2.0 * c33;
      const double step = next - c33;
      c33 = next;
      f = S33(c33);
      (f > 0.0 ? hi : lo) = c33;
      done = converged() || std::abs(step) <= 1e-15 * c33;
      if (!std::isfinite(f)) break;
    }
    if (!done) throw std::runtime_error("plane stress: thickness iteration did not converge");
  }
  // In-plane only, so it leaves the thickness solved above as it is (docs/physics.md §2.5).
  material.add_membrane_overstress(C, point, history_old, history_new, S, D);
  return condensed_state(S, D, c33, det2);
}

PlaneStressState condensed_state(const Eigen::Matrix3d& S, const Voigt6& D, double c33,
                                 double det2) {
  PlaneStressState state;
  state.C33 = c33;
  state.J2 = c33 * det2;
  state.S = S.topLeftCorner<2, 2>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      state.D(i, j) = D(kPlane[i], kPlane[j]) - D(kPlane[i], k33) * D(k33, kPlane[j]) / D(k33, k33);
  return state;
}

}  // namespace vesica::simulate
