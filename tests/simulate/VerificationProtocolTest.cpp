// The inflated sphere of docs/physics.md §6.1–6.2 run by the verification protocols
// (pressure and volume steps): its P–λ table within 0.3 % of the thin sphere computed here
// independently, for the Ogden volumetric term (β = 9) and FEBio's K/2 (ln J)², at K/μ = 2
// and 500, up to the limit point under pressure and past it under volume.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "ShellCommand.h"
#include "TestData.h"
#include "vesica/simulate/verification/VerificationProtocol.h"
#include "vesica/simulate/wall/SphereMesh.h"

using namespace vesica::simulate;

namespace {

constexpr double kR = 0.030, kH = 3e-3, kMu = 5e3;

// Thin sphere, equibiaxial in-plane stretch λ, neo-Hookean isochoric part: λ3 from S33 = 0
// by bisection, then σ = λ² S11 / J and P = 2 (h/r) σ. The volumetric law enters through
// J dΨ/dJ: K ln J (β = 0) or (K/β)(1 − J^(−β)).
double thin_sphere_pressure(double l, double K, double beta, double R = kR) {
  auto S = [&](double l3, double stretch2) {  // S_ii of C = diag(λ², λ², λ3²)
    const double J = l * l * l3, I1 = 2 * l * l + l3 * l3;
    const double vol = beta == 0.0 ? K * std::log(J) : K / beta * (1.0 - std::pow(J, -beta));
    return kMu * std::pow(J, -2.0 / 3.0) * (1.0 - I1 / (3.0 * stretch2)) + vol / stretch2;
  };
  double lo = 1e-3, hi = 1.5;  // S33 increases with λ3
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    (S(mid, mid * mid) > 0.0 ? hi : lo) = mid;
  }
  const double l3 = 0.5 * (lo + hi), J = l * l * l3;
  return 2.0 * (l3 * kH) / (l * R) * (l * l * S(l3, l * l) / J);
}

double limit_pressure(double K, double beta, double* at = nullptr) {
  double best = 0.0;
  for (double l = 1.0; l < 2.0; l += 1e-4) {
    const double p = thin_sphere_pressure(l, K, beta);
    if (p > best) {
      best = p;
      if (at) *at = l;
    }
  }
  return best;
}

MaterialSpec material(double K_per_mu, double beta) {
  return {"neo-hookean", {{"mu", kMu}, {"K", K_per_mu * kMu}, {"beta_vol", beta}}};
}

WallModel balloon() {
  WallModel wall = sphere_wall(kR, kH, 16);
  hold_rigid_body_modes(wall);
  return wall;
}

// Every row within `tolerance` of the thin sphere at its own λ; returns the largest λ. The
// sphere has the radius of the mesh's volume (λ is measured by volume): the inscribed
// polyhedron encloses less than the sphere through its nodes.
double expect_on_thin_sphere(const VerificationResult& r, double K, double beta,
                             double tolerance = 3e-3) {
  const double R = std::cbrt(3.0 * r.reference_volume_m3 / (4.0 * 3.14159265358979323846));
  double worst = 0.0, l_max = 1.0;
  for (const StretchRow& row : r.rows) {
    if (row.pressure_pa == 0.0) continue;
    const double exact = thin_sphere_pressure(row.stretch, K, beta, R);
    worst = std::max(worst, std::abs(row.pressure_pa / exact - 1.0));
    EXPECT_NEAR(row.pressure_pa, exact, tolerance * exact) << "λ = " << row.stretch;
    l_max = std::max(l_max, row.stretch);
  }
  std::cout << "[ verification ] K/mu = " << K / kMu << ", beta " << beta << ": " << r.rows.size()
            << " rows to λ = " << l_max << ", worst deviation " << worst << std::endl;
  return l_max;
}

}  // namespace

// The independent root solve reproduces the limit pressures of docs/physics.md §6.2.
TEST(VerificationProtocol, ThinSphereLimitPressuresOfBothVolumetricLaws) {
  EXPECT_NEAR(limit_pressure(2 * kMu, 9.0), 199.0, 1.0);
  EXPECT_NEAR(limit_pressure(2 * kMu, 0.0), 404.0, 2.0);
}

TEST(VerificationProtocol, PressureStepsFollowTheBalloonUpToItsLimitPoint) {
  const WallModel wall = balloon();
  for (double K_per_mu : {2.0, 500.0})
    for (double beta : {9.0, 0.0}) {
      const double K = K_per_mu * kMu;
      VerificationSettings s;
      s.protocol = "pressure-steps";
      s.steps = 10;
      s.max_pressure_cmh2o = 0.95 * limit_pressure(K, beta) / 98.0665;
      const VerificationResult r = run_verification(wall, material(K_per_mu, beta), s);
      ASSERT_TRUE(r.completed) << r.failure;
      EXPECT_TRUE(r.note.empty()) << r.note;
      EXPECT_EQ(r.rows.size(), 11u);
      expect_on_thin_sphere(r, K, beta);
    }
}

TEST(VerificationProtocol, VolumeStepsGoPastTheLimitPointDownTheFallingBranch) {
  const WallModel wall = balloon();
  for (double K_per_mu : {2.0, 500.0})
    for (double beta : {9.0, 0.0}) {
      const double K = K_per_mu * kMu;
      double l_peak = 1.0;
      limit_pressure(K, beta, &l_peak);
      VerificationSettings s;
      s.protocol = "volume-steps";
      s.steps = 16;
      s.max_stretch = l_peak + 0.2;
      const VerificationResult r = run_verification(wall, material(K_per_mu, beta), s);
      ASSERT_TRUE(r.completed) << r.failure;
      EXPECT_GT(expect_on_thin_sphere(r, K, beta), l_peak + 0.15);
      EXPECT_LT(r.rows.back().pressure_pa, limit_pressure(K, beta));  // on the falling branch
    }
}

// Pressure steps past the limit point stop there with a note, not an error.
TEST(VerificationProtocol, PressureStepsPastTheLimitStopAtIt) {
  VerificationSettings s;
  s.protocol = "pressure-steps";
  s.steps = 5;
  const double limit = limit_pressure(2 * kMu, 9.0);
  s.max_pressure_cmh2o = 1.5 * limit / 98.0665;
  const VerificationResult r = run_verification(balloon(), material(2.0, 9.0), s);
  EXPECT_TRUE(r.completed);
  EXPECT_FALSE(r.note.empty());
  // The limit of the sphere with the mesh's volume (P ∝ 1/R).
  const double R = std::cbrt(3.0 * r.reference_volume_m3 / (4.0 * 3.14159265358979323846));
  const double mesh_limit = limit * kR / R;
  std::cout << "[ verification ] pressure steps stop at " << r.rows.back().pressure_pa
            << " Pa, limit " << mesh_limit << " Pa: " << r.note << std::endl;
  EXPECT_NEAR(r.rows.back().pressure_pa, mesh_limit, 3e-3 * mesh_limit);
}

// The Ogden term at β = 1e-4 (nearly the log law) converges to the tight tolerances and
// follows its own thin sphere: without the expm1 form its stress had lost the digits
// Newton's last iterations need.
TEST(VerificationProtocol, SmallBetaOgdenConverges) {
  const double K = 2 * kMu, beta = 1e-4;
  VerificationSettings s;
  s.protocol = "pressure-steps";
  s.steps = 8;
  s.max_pressure_cmh2o = 0.9 * limit_pressure(K, beta) / 98.0665;
  const VerificationResult r = run_verification(balloon(), material(2.0, beta), s);
  ASSERT_TRUE(r.completed) << r.failure;
  EXPECT_TRUE(r.note.empty()) << r.note;
  expect_on_thin_sphere(r, K, beta);
}

// From the command line: the P–λ table with its units, one row per step after the
// reference, and the summary naming the protocol.
TEST(VerificationProtocol, CommandLineWritesThePressureStretchTable) {
  using namespace vesica::test;
  const std::filesystem::path dir = scratch_dir("verification-cli");
  const std::string bin = bin_dir().string();
  CommandResult r = run_command(bin + "/vesica-surface -o " + (dir / "sphere.vtp").string() +
                                " --shape sphere --volume-ml 113 --edge-mm 8");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = run_command(bin + "/vesica-simulate " + (dir / "sphere.vtp").string() + " -o " +
                  (dir / "out").string() +
                  " --protocol volume-steps --steps 3 --max-stretch 1.1 --beta-vol 0 --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("\"protocol\": \"volume-steps\""), std::string::npos) << r.output;
  std::ifstream csv(dir / "out" / "pressure_stretch.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line,
            "step,pressure_pa,pressure_cmh2o,volume_ml,stretch,newton_iterations,"
            "foundation_iterations");
  int rows = 0;
  double stretch = 0.0;
  while (std::getline(csv, line)) {
    ++rows;
    stretch = std::stod(line.substr(line.rfind(',', line.rfind(',', line.rfind(',') - 1) - 1) + 1));
  }
  EXPECT_EQ(rows, 4);
  EXPECT_NEAR(stretch, 1.1, 1e-9);
}
