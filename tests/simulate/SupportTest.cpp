// Elastic support and wall weight (issue 6 "loads and supports").
//  - A sphere held only by springs k (Pa/m, per reference area) on its whole wall and
//    inflated by p: virtual work on the uniform expansion λ gives
//      p = P_s(λ) + k R (λ - 1) / λ²,  P_s = 2 (H/R) μ (λ⁻¹ - λ⁻⁷)  (K ≫ μ).
//  - The fixed dofs carry the wall's weight ρ_w g Σ H A0.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "solver/NewtonSolver.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/wall/SphereMesh.h"
#include "wall/MembraneProblem.h"

using namespace vesica::simulate;

namespace {
constexpr double kR = 0.03, kH = 3e-3, kMu = 5e3;

double spring_sphere_pressure(double l, double k) {
  return 2.0 * kH / kR * kMu * (1.0 / l - std::pow(l, -7)) + k * kR * (l - 1.0) / (l * l);
}
}  // namespace

TEST(Support, SpringHeldSphereMatchesVirtualWork) {
  WallModel wall = sphere_wall(kR, kH, 12);
  wall.fixed.assign(wall.node_count(), {false, false, false});
  wall.support.assign(wall.node_count(), true);  // springs everywhere, nothing fixed
  const auto material = make_material({"neo-hookean", {{"mu", kMu}, {"K", 1e3 * kMu}}});
  MembraneProblem problem(wall, *material, 2);
  NewtonSolver solver(problem);
  WallLoads loads;
  const double k = 1e5;  // Pa/m: springs carry about as much as the wall at λ = 1.2
  loads.support_stiffness = k;
  std::vector<Eigen::Vector3d> x = wall.nodes;
  const double V0 = enclosed_volume(wall, x);
  for (double p = 100.0; p <= 1000.0 + 1e-9; p += 100.0) {
    CavityEquation cavity;
    cavity.pressure_pa = p;
    const NewtonReport report = solver.solve(cavity, loads, x);
    ASSERT_TRUE(report.converged) << report.failure << " at p = " << p;
    problem.commit();
    const double l = std::cbrt(solver.assembly().volume / V0);
    EXPECT_NEAR(spring_sphere_pressure(l, k), p, 0.01 * p) << "λ = " << l;
    if (p == 1000.0) std::cout << "[ support ] p = 1000 Pa: λ = " << l << std::endl;
  }
}

TEST(Support, FixedDofsCarryTheWallWeight) {
  WallModel wall = sphere_wall(kR, kH, 12);
  fix_sphere_rigid_modes(wall);
  const auto material = make_material({"neo-hookean", {{"mu", kMu}, {"K", 1e3 * kMu}}});
  MembraneProblem problem(wall, *material, 2);
  NewtonOptions options;
  options.max_iterations = 40;  // the weight hangs on one point: a large local dent
  NewtonSolver solver(problem, options);
  WallLoads loads;
  loads.wall_density = 920.0;
  std::vector<Eigen::Vector3d> x = wall.nodes;
  CavityEquation cavity;
  cavity.pressure_pa = 300.0;  // taut wall first, then its weight
  ASSERT_TRUE(solver.solve(cavity, loads, x).converged);
  problem.commit();
  loads.wall_gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  const NewtonReport report = solver.solve(cavity, loads, x);
  ASSERT_TRUE(report.converged) << report.failure;
  double area = 0.0;
  for (const auto& t : wall.triangles)
    area += 0.5 *
            (wall.nodes[t[1]] - wall.nodes[t[0]]).cross(wall.nodes[t[2]] - wall.nodes[t[0]]).norm();
  const double weight = 920.0 * 9.81 * kH * area;
  Eigen::Vector3d reaction = Eigen::Vector3d::Zero();
  const Eigen::VectorXd& r = solver.assembly().full_residual;
  for (std::size_t n = 0; n < wall.node_count(); ++n)
    for (int i = 0; i < 3; ++i)
      if (problem.dof_map()[3 * n + i] < 0) reaction(i) += r(3 * n + i);  // r = f_int - f_ext = R
  std::cout << "[ support ] wall weight " << weight << " N, reaction " << reaction.transpose()
            << std::endl;
  // The supports push up (+z) with the weight.
  EXPECT_NEAR(reaction.z(), weight, 1e-6 * weight);
  EXPECT_NEAR(reaction.x(), 0.0, 1e-6 * weight);
  EXPECT_NEAR(reaction.y(), 0.0, 1e-6 * weight);
}
