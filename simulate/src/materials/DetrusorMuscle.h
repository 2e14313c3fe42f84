#pragma once
// The detrusor's smooth muscle as an active fiber stress along both fiber families
// (docs/physics.md §2.6). Its nominal (first Piola–Kirchhoff) stress along a fiber of
// stretch λ = √(C : A), A = a0 ⊗ a0, is
//   P_a = T · f_l(λ) · f_v(v),   T = tone + a · contractility,
// with the activation a ∈ [0, 1] of the protocol (MaterialPoint::activation), the
// length–tension factor f_l(λ) = exp(−((λ − λ_opt)/w)²) and the Hill force–velocity factor
// f_v of the fiber's shortening rate v = −d ln λ/dt (backward Euler against the last
// committed stretch). As a second Piola–Kirchhoff stress, S_a = (P_a/λ) A: a Cauchy stress
// P_a λ along the current fiber, so that a thinning wall keeps the force of its cells.
// The full I4 (not the isochoric one) keeps the stress in the plane: it never loads the
// thickness direction, whatever the volume ratio. The tangent D_a = 2 dg/dI4 A ⊗ A with
// g = P_a/λ is symmetric.
#include <cstddef>

#include <Eigen/Dense>

#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/materials/Voigt.h"

namespace vesica::simulate {

struct MuscleParameters {
  double tone = 0.0;             // nominal active stress at rest, a = 0 (Pa)
  double contractility = 0.0;    // added at full activation, a = 1 (Pa)
  double optimal_stretch = 2.0;  // λ_opt of the length–tension curve (from the reference)
  double stretch_width = 1.0;    // w of the length–tension curve
  double hill_a = 0.25;          // Hill's a/T0 (curvature of the force–velocity hyperbola)
  double hill_vmax = 0.1;        // unloaded shortening rate (1/s)
  double eccentric_max = 1.5;    // f_v for fast lengthening (v → −∞)
};

// The Hill factor f_v(v) and its derivative with respect to v (v in 1/s, shortening > 0):
//   v ≥ 0: f_v = (1 − v/v_max) / (1 + v/(k v_max)), 0 beyond v_max (k = hill_a);
//   v < 0: f_v = e − (e − 1) / (1 − v/c), e = eccentric_max, c = (e − 1) k v_max / (1 + k),
// continuous with its slope at v = 0.
struct HillFactor {
  double value = 1.0;
  double d_dv = 0.0;
};
HillFactor hill_factor(const MuscleParameters& m, double v);

class DetrusorMuscle {
 public:
  explicit DetrusorMuscle(const MuscleParameters& parameters) : m_(parameters) {}
  const MuscleParameters& parameters() const { return m_; }
  // Whether it can carry stress at all (tone or contractility).
  bool active() const { return m_.tone > 0.0 || m_.contractility > 0.0; }

  // Per family: the committed stretch and Hill factor (the rate's reference, and the
  // factor kept through a step without time), stored as λ − 1 and f_v − 1 so that a
  // zeroed history is the reference state at rest.
  static constexpr std::size_t kHistorySize = 4;

  // Adds S_a and D_a at C. With point.dt_s = 0 the Hill factor is the committed one.
  void add_stress(const Eigen::Matrix3d& C, const MaterialPoint& point, const double* history_old,
                  double* history_new, Eigen::Matrix3d& S, Voigt6& D) const;

 private:
  MuscleParameters m_;
};

}  // namespace vesica::simulate
