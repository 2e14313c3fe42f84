// The detrusor's active fiber stress (docs/physics.md §2.6) against values worked by hand:
// the Hill force–velocity factor, the length–tension factor and the stress of a fiber held
// (isometric) or shortening at a known rate. One fiber family along x (the second along z,
// out of the way), C = diag(λ², 1/λ, 1/λ), so that the fiber stretch is λ exactly.
#include <gtest/gtest.h>

#include <cmath>

#include "materials/DetrusorMuscle.h"

using namespace vesica::simulate;

namespace {

MuscleParameters muscle() {
  MuscleParameters m;
  m.tone = 2e3;
  m.contractility = 100e3;
  m.optimal_stretch = 2.0;
  m.stretch_width = 1.0;
  m.hill_a = 0.25;
  m.hill_vmax = 0.1;
  m.eccentric_max = 1.5;
  return m;
}

// S11 of the muscle alone for a fiber of stretch λ after a step dt from the committed
// stretch λ_old (and committed Hill factor fv_old).
double fiber_stress(double lambda, double lambda_old, double dt, double activation,
                    double fv_old = 1.0, double* history_out = nullptr) {
  const DetrusorMuscle m(muscle());
  MaterialPoint point;
  point.fibers = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitZ()};
  point.dt_s = dt;
  point.activation = activation;
  const Eigen::Matrix3d C =
      Eigen::Vector3d(lambda * lambda, 1.0 / lambda, 1.0 / lambda).asDiagonal();
  const double z = std::sqrt(C(2, 2));  // the z family's stretch: keep it isometric
  double history_old[4] = {lambda_old - 1.0, fv_old - 1.0, z - 1.0, 0.0};
  double history_new[4];
  Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
  Voigt6 D = Voigt6::Zero();
  m.add_stress(C, point, history_old, history_new, S, D);
  if (history_out)
    for (int i = 0; i < 4; ++i) history_out[i] = history_new[i];
  return S(0, 0);
}

}  // namespace

// Hill's hyperbola with a/T0 = 0.25, v_max = 0.1 /s: (1 − v/v_max)/(1 + 4 v/v_max), so
// f(0) = 1, f(0.05) = 0.5/3, f(v_max) = 0 and 0 beyond; lengthening tends to 1.5 and meets
// the shortening branch with the same slope, −(1 + 1/0.25)/v_max = −50 s.
TEST(DetrusorMuscle, HillFactorIsTheForceVelocityHyperbola) {
  const MuscleParameters m = muscle();
  EXPECT_NEAR(hill_factor(m, 0.0).value, 1.0, 1e-15);
  EXPECT_NEAR(hill_factor(m, 0.05).value, 0.5 / 3.0, 1e-15);
  EXPECT_NEAR(hill_factor(m, 0.025).value, 0.75 / 2.0, 1e-15);
  EXPECT_EQ(hill_factor(m, 0.1).value, 0.0);
  EXPECT_EQ(hill_factor(m, 0.3).value, 0.0);
  EXPECT_NEAR(hill_factor(m, -1e6).value, 1.5, 1e-5);
  EXPECT_NEAR(hill_factor(m, 0.0).d_dv, -50.0, 1e-12);
  EXPECT_NEAR(hill_factor(m, -1e-12).d_dv, -50.0, 1e-6);
  // Power P·v of the hyperbola peaks at v = v_max (√(a² + a) − a) ≈ 0.0309 /s (a = 0.25).
  const double v_best = 0.1 * (std::sqrt(0.25 * 0.25 + 0.25) - 0.25);
  const double power = v_best * hill_factor(m, v_best).value;
  EXPECT_GT(power, (v_best * 0.99) * hill_factor(m, v_best * 0.99).value);
  EXPECT_GT(power, (v_best * 1.01) * hill_factor(m, v_best * 1.01).value);
  for (double v : {-0.05, 0.01, 0.07}) {
    const double h = 1e-7;
    const double fd = (hill_factor(m, v + h).value - hill_factor(m, v - h).value) / (2 * h);
    EXPECT_NEAR(hill_factor(m, v).d_dv, fd, 1e-6 * std::abs(fd)) << v;
  }
}

// Held at λ = 1.5: f_l = exp(−0.25) = 0.778800783; the nominal stress is
// (tone + a·contractility) f_l and S11 = that / λ. At rest (a = 0) only the tone acts.
TEST(DetrusorMuscle, IsometricFiberCarriesToneAndContractilityTimesLengthTension) {
  const double fl = std::exp(-0.25);
  EXPECT_NEAR(fiber_stress(1.5, 1.5, 0.5, 0.0), 2e3 * fl / 1.5, 1e-9);
  EXPECT_NEAR(fiber_stress(1.5, 1.5, 0.5, 1.0), 102e3 * fl / 1.5, 1e-8);
  EXPECT_NEAR(fiber_stress(1.5, 1.5, 0.5, 0.4), 42e3 * fl / 1.5, 1e-8);
  // At the optimum the factor is 1: the Cauchy stress λ² S11 = λ · 102 kPa.
  EXPECT_NEAR(2.0 * 2.0 * fiber_stress(2.0, 2.0, 0.5, 1.0), 2.0 * 102e3, 1e-7);
}

// Shortening from λ_old = 1.5 e^(0.05 · 0.4) to λ = 1.5 in 0.4 s is v = 0.05 /s: the
// stress falls to 1/6 of the isometric one. A step without time keeps the committed
// factor (0.8 here), and the step's history holds λ − 1 and f_v − 1.
TEST(DetrusorMuscle, ShorteningFiberLosesForceAlongTheHillRelation) {
  const double fl = std::exp(-0.25), isometric = 102e3 * fl / 1.5;
  double history[4];
  EXPECT_NEAR(fiber_stress(1.5, 1.5 * std::exp(0.02), 0.4, 1.0, 1.0, history),
              isometric * 0.5 / 3.0, 1e-8);
  EXPECT_NEAR(history[0], 0.5, 1e-15);
  EXPECT_NEAR(history[1], 0.5 / 3.0 - 1.0, 1e-12);
  EXPECT_NEAR(fiber_stress(1.5, 1.7, 0.0, 1.0, 0.8), isometric * 0.8, 1e-8);
  // Faster than v_max: no force at all.
  EXPECT_EQ(fiber_stress(1.5, 1.5 * std::exp(0.05), 0.4, 1.0), 0.0);
}
