// Bossak–Newmark dynamics of the wall (docs/physics.md §3) against an independent solution:
// a thin incompressible neo-Hookean sphere under a suddenly applied inside pressure p
// moves radially by Lagrange's equation for its one degree of freedom λ = r/R,
//   ρ_w H R λ'' = λ² (p - P_s(λ)),  P_s(λ) = 2 (H/R) μ (λ⁻¹ - λ⁻⁷),
// which the test integrates with a fine fourth-order Runge–Kutta and compares with the
// finite-element sphere's λ(t) = (V/V0)^(1/3).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "solver/BossakNewmark.h"
#include "solver/NewtonSolver.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/wall/SphereMesh.h"
#include "wall/MembraneProblem.h"

using namespace vesica::simulate;

namespace {

constexpr double kR = 0.03, kH = 3e-3, kMu = 5e3, kRho = 920.0;

double static_pressure(double l) {
  return 2.0 * kH / kR * kMu * (1.0 / l - std::pow(l, -7));
}

// λ(t) of the one-degree-of-freedom sphere, sampled every dt, by RK4 with 100 substeps.
std::vector<double> sphere_ode(double p, double dt, int steps) {
  auto accel = [p](double l) { return l * l * (p - static_pressure(l)) / (kRho * kH * kR); };
  std::vector<double> out{1.0};
  double l = 1.0, v = 0.0;
  const int sub = 100;
  const double h = dt / sub;
  for (int s = 0; s < steps; ++s) {
    for (int k = 0; k < sub; ++k) {
      const double k1l = v, k1v = accel(l);
      const double k2l = v + 0.5 * h * k1v, k2v = accel(l + 0.5 * h * k1l);
      const double k3l = v + 0.5 * h * k2v, k3v = accel(l + 0.5 * h * k2l);
      const double k4l = v + h * k3v, k4v = accel(l + h * k3l);
      l += h / 6.0 * (k1l + 2 * k2l + 2 * k3l + k4l);
      v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
    out.push_back(l);
  }
  return out;
}

struct DynamicSphere {
  WallModel wall = sphere_wall(kR, kH, 8);
  std::unique_ptr<Material> material =
      make_material({"neo-hookean", {{"mu", kMu}, {"K", 1e3 * kMu}}});
  std::unique_ptr<MembraneProblem> problem;
  std::unique_ptr<NewtonSolver> solver;
  WallLoads loads;
  std::vector<Eigen::Vector3d> x;
  double V0 = 0.0;

  DynamicSphere() {
    fix_sphere_rigid_modes(wall);
    problem = std::make_unique<MembraneProblem>(wall, *material, 2);
    solver = std::make_unique<NewtonSolver>(*problem);
    x = wall.nodes;
    V0 = enclosed_volume(wall, x);
    loads.wall_density = kRho;
  }

  // λ(t) at every step of a pressure step p held for `steps` steps of dt.
  std::vector<double> run(double p, double dt, int steps, double alpha_b) {
    BossakNewmark integrator(wall.node_count(), alpha_b);
    std::vector<double> out{1.0};
    CavityEquation cavity;
    cavity.pressure_pa = p;
    for (int s = 0; s < steps; ++s) {
      const std::vector<Eigen::Vector3d> x_n = x;
      loads.inertia = integrator.inertia(x_n, dt);
      loads.dt_s = dt;
      const NewtonReport report = solver->solve(cavity, loads, x);
      EXPECT_TRUE(report.converged) << report.failure << " at step " << s;
      if (!report.converged) break;
      problem->commit();
      integrator.commit(x_n, x, dt);
      out.push_back(std::cbrt(solver->assembly().volume / V0));
    }
    return out;
  }
};

}  // namespace

TEST(Dynamics, PressureStepOscillationMatchesTheSphereEquation) {
  const double p = 0.5 * static_pressure(std::pow(7.0, 1.0 / 6.0));
  const double period = 2.0 * 3.14159265358979 / std::sqrt(12.0 * kMu / (kRho * kR * kR));
  const double dt = period / 100.0;
  const int steps = 150;  // about one and a half periods of the large oscillation
  DynamicSphere sphere;
  const std::vector<double> fe = sphere.run(p, dt, steps, 0.0);
  const std::vector<double> ode = sphere_ode(p, dt, steps);
  ASSERT_EQ(fe.size(), ode.size());
  double amplitude = 0.0, worst = 0.0;
  for (double l : ode) amplitude = std::max(amplitude, l - 1.0);
  for (std::size_t i = 0; i < fe.size(); ++i) worst = std::max(worst, std::abs(fe[i] - ode[i]));
  std::cout << "[ dynamics ] α_B = 0: λ overshoots to " << 1.0 + amplitude
            << ", largest |λ_FE - λ_ODE| / amplitude = " << worst / amplitude << std::endl;
  EXPECT_GT(amplitude, 0.05);
  EXPECT_LT(worst, 0.02 * amplitude);
}

TEST(Dynamics, BossakDampingSettlesOnTheStaticState) {
  // α_B = -1/3 damps what the step cannot resolve: with Δt = one period of the small
  // oscillation each step shrinks the oscillation, so the sphere settles on the static
  // stretch P_s(λ) = p (rising branch) while α_B = 0 would keep it ringing.
  const double p = 0.5 * static_pressure(std::pow(7.0, 1.0 / 6.0));
  const double period = 2.0 * 3.14159265358979 / std::sqrt(12.0 * kMu / (kRho * kR * kR));
  DynamicSphere sphere;
  const std::vector<double> l = sphere.run(p, period, 30, -1.0 / 3.0);
  double lo = 1.0, hi = std::pow(7.0, 1.0 / 6.0);
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (static_pressure(mid) < p ? lo : hi) = mid;
  }
  const double l_static = 0.5 * (lo + hi);
  const double first_error = std::abs(l[1] - l_static);
  std::cout << "[ dynamics ] α_B = -1/3, Δt = T: λ after 1 step " << l[1] << ", after 30 "
            << l.back() << ", static " << l_static << std::endl;
  // Settled: the last steps no longer move, and at rest the sphere carries p statically
  // (within the 2 % the coarse 512-triangle sphere allows).
  EXPECT_GT(first_error, 1e2 * std::abs(l[30] - l[29]));
  EXPECT_NEAR(static_pressure(l.back()), p, 0.02 * p);
}
