// Level-1 wall-urine coupling (docs/physics.md §4-5):
//  - hydrostatics: the fixed base carries the urine's weight ρ g V within 0.5 %;
//  - a stiff sphere drained through a linear outlet law follows the analytic exponential
//    V - V0 = ΔV e^(-t/(R1 C)), C = dV/dP = R V0 / (4 H μ) from the balloon formula;
//  - mass balance |V - V0 - ∫(Qin - Qout)dt| < 1e-6 V at every step;
//  - bad input: a protocol above the geometry's limits is refused before any work.
#include <gtest/gtest.h>

#include <cmath>

#include "solver/NewtonSolver.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/SphereMesh.h"
#include "wall/MembraneProblem.h"

using namespace vesica;
using namespace vesica::simulate;

// A balloon in air held at its base, inflated (no gravity) until its pressure exceeds
// the hydrostatic range ρ g 2R, then gravity switched on in steps at constant volume.
TEST(Cavity, SupportCarriesTheUrineWeight) {
  const double R = 0.03, H = 3e-3, rho = 1000.0, g = 9.81;
  WallModel wall = sphere_wall(R, H, 12);
  for (std::size_t n = 0; n < wall.node_count(); ++n)
    if (wall.nodes[n].z() < -0.9 * R) wall.fixed[n] = {true, true, true};
  const auto m = make_material({"neo-hookean", {{"mu", 50e3}, {"K", 100e3}}});
  MembraneProblem problem(wall, *m, 2);
  NewtonSolver solver(problem);
  WallLoads loads;
  loads.inside.gravity = Eigen::Vector3d(0.0, 0.0, -g);
  loads.inside.x_ref = Eigen::Vector3d(0.0, 0.0, -R);
  std::vector<Eigen::Vector3d> x = wall.nodes;
  const double V0 = enclosed_volume(wall, x);
  for (int k = 0; k <= 8; ++k) {
    CavityEquation c;
    c.volume_control = true;
    c.volume_base_m3 = std::min(1.0 + 0.1 * k, 1.3) * V0;
    loads.inside.rho = k > 3 ? rho * (k - 3) / 5.0 : 0.0;
    const NewtonReport report = solver.solve(c, loads, x);
    ASSERT_TRUE(report.converged) << report.failure << " in load step " << k;
    problem.commit();
  }
  double up = 0.0;  // force of the fixed base on the wall, upward
  for (std::size_t n = 0; n < wall.node_count(); ++n)
    if (wall.fixed[n][2]) up += solver.assembly().full_residual(3 * n + 2);
  const double weight = rho * g * solver.assembly().volume;
  std::cout << "[ hydrostatics ] reaction " << up << " N, urine weight " << weight << " N, p0 "
            << loads.inside.p0 << " Pa" << std::endl;
  EXPECT_NEAR(up, weight, 0.005 * weight);
}

TEST(Cavity, StiffSphereDrainsExponentiallyWithMassBalance) {
  const double R = 0.0229, H = 3e-3, mu = 5e5;
  WallModel wall = sphere_wall(R, H, 8);
  fix_sphere_rigid_modes(wall);
  const double V0 = enclosed_volume(wall, wall.nodes);
  const double Rh = std::cbrt(3.0 * V0 / (4.0 * 3.14159265358979323846));
  // dP/dV of the balloon at λ = 1 (docs/physics.md §6 linearised), in cmH2O per ml.
  const double dPdV = units::cmh2o_from_pa(4.0 * H * mu / (Rh * V0)) * units::kM3PerMl;
  const double tau = 1.0, R1 = tau * dPdV;  // R1 C = τ
  ProtocolSettings p;
  p.start_ml = units::ml_from_m3(V0);
  const double dV_ml = 1e-4 * p.start_ml;
  p.capacity_ml = p.start_ml + dV_ml;
  p.fill_rate_ml_min = 60.0 * dV_ml / 0.01;  // fills within 0.01 s
  p.p_open_cmh2o = 0.0;
  p.p_close_cmh2o = 0.0;
  p.urethra_half_open_cmh2o = 0.0;  // rigid: Q = p / R1
  p.r1_cmh2o_s_per_ml = R1;
  p.r2_cmh2o_s2_per_ml2 = 0.0;
  p.gravity = false;
  p.stop_flow_ml_s = 1e-9;
  p.max_void_s = 2.0 * tau;
  RunOptions o;
  o.max_void_step_s = 0.02;
  const CystometryResult r =
      run_cystometry(wall, {"neo-hookean", {{"mu", mu}, {"K", 1e3 * mu}}}, p, o);
  ASSERT_TRUE(r.completed) << r.failure;
  double t_void = -1.0, worst = 0.0, mass = 0.0;
  for (const HistoryRow& row : r.history) {
    const double expected_V = p.start_ml + row.infused_ml - row.voided_ml;
    mass = std::max(mass, std::abs(row.volume_ml - expected_V) / row.volume_ml);
    if (t_void < 0.0 && row.infused_ml >= dV_ml * (1 - 1e-9)) t_void = row.time_s;
    if (t_void < 0.0 || row.time_s <= t_void) continue;
    const double analytic = dV_ml * std::exp(-(row.time_s - t_void) / tau);
    worst = std::max(worst, std::abs((row.volume_ml - p.start_ml) / analytic - 1.0));
  }
  std::cout << "[ drain ] worst deviation from the exponential " << worst << ", mass balance "
            << mass << std::endl;
  EXPECT_LT(worst, 0.01);
  EXPECT_LT(mass, 1e-6);
  EXPECT_GT(r.history.back().time_s - t_void, 1.9 * tau);
}

TEST(Cavity, ProtocolAboveGeometryLimitIsRefused) {
  WallModel wall = sphere_wall(0.0229, 3e-3, 6);
  fix_sphere_rigid_modes(wall);
  ProtocolSettings p;
  p.capacity_ml = 5000.0;  // 100 times the 50 ml reference
  try {
    run_cystometry(wall, {"neo-hookean", {}}, p, RunOptions{});
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("capacity_ml"), std::string::npos) << e.what();
  }
}

// Below its stress-free volume a wrinkling wall is shorter than its reference in every
// direction and carries no stress, so it transmits no pressure: Pves = Pabd up to the
// tissue drag, which resists the wall's inward velocity v = Q / A with c v per unit
// reference area A0, i.e. a pressure c Q A0 / A² on the current area A, largest for the
// smallest A a surface of volume V can have, a sphere's. So 0 ≥ Pdet ≥ -c Q A0 / A_sphere(V)²,
// with 10 % for the held outlet cap (it does not move, so the rest moves faster) and for
// the step's mean velocity against the flow at its end.
// (The plain law compresses the wall instead: by the balloon formula 2 σ h / r with the
// compressive σ = μ (λ² - λ⁻⁴), about -30 cmH2O of Pdet at half the reference volume.)
TEST(Cavity, SlackWallBelowItsReferenceTransmitsOnlyTheTissueDrag) {
  const double pi = 3.14159265358979323846;
  const double R = std::cbrt(3.0 * units::m3_from_ml(50.0) / (4.0 * pi));
  WallModel wall = sphere_wall(R, 3e-3, 10);
  for (std::size_t e = 0; e < wall.triangle_count(); ++e) {
    bool base = true;
    for (int v : wall.triangles[e]) base = base && wall.nodes[v].z() < -0.93 * R;
    if (base) wall.region[e] = 2;  // outlet cap, held
  }
  fix_regions(wall, Eigen::Vector3d(0, 0, -1), 0.0);
  double A0 = 0.0;
  for (const auto& t : wall.triangles)
    A0 += 0.5 *
          (wall.nodes[t[1]] - wall.nodes[t[0]]).cross(wall.nodes[t[2]] - wall.nodes[t[0]]).norm();
  ProtocolSettings p;
  p.capacity_ml = 60.0;
  p.fill_rate_ml_min = 600.0;
  p.drive = VoidingDrive::Straining;
  p.straining_kpa = 4.0;
  p.wrinkle_regularisation = 0.0;  // the pure tension field of physics.md §1.5, whose bound this is
  const CystometryResult r =
      run_cystometry(wall, {"neo-hookean", {{"mu", 3e3}, {"K_per_mu", 1e3}}}, p, RunOptions{});
  ASSERT_TRUE(r.completed) << r.failure;
  int rows = 0;
  double most_positive = -1e9, worst_ratio = 0.0;
  for (const HistoryRow& row : r.history) {
    if (row.voided_ml <= 0.0 || row.volume_ml > 40.0 || row.volume_ml < 5.0) continue;
    ++rows;
    const double V = units::m3_from_ml(row.volume_ml);
    const double A_sphere = 4.0 * pi * std::pow(3.0 * V / (4.0 * pi), 2.0 / 3.0);
    const double drag_bound = units::cmh2o_from_pa(
        p.wall_drag_pa_s_per_m * units::m3s_from_mls(row.flow_ml_s) * A0 / (A_sphere * A_sphere));
    most_positive = std::max(most_positive, row.pdet_cmh2o);
    worst_ratio = std::max(worst_ratio, -row.pdet_cmh2o / drag_bound);
  }
  std::cout << "[ slack ] " << rows << " rows between 40 and 5 ml: Pdet <= " << most_positive
            << " cmH2O, at most " << worst_ratio << " of the drag bound" << std::endl;
  EXPECT_GE(rows, 5);
  EXPECT_LT(most_positive, 0.01);  // no tension reaches the urine
  EXPECT_LE(worst_ratio, 1.1);
}
