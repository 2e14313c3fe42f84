// Level 0, the lumped sphere-equivalent bladder (docs/physics.md §11), against answers
// computed independently of it:
//  - the thin incompressible balloon (§6.1), P = 2 (H/R) μ (λ⁻¹ − λ⁻⁷), on both sides of
//    its limit point, from the sphere-equivalent's own R and H;
//  - the bladder output relation (§12): with the detrusor's active stress alone, the
//    pressure it keeps while the bladder empties at flow Q is its isovolumetric pressure
//    times Hill's factor of the wall's shortening rate v = Q / (3 V), i.e. Griffiths'
//    hyperbola (P + a)(v + b) = (P_iso + a) b with a = (a/T0) P_iso, b = (a/T0) v_max;
//  - the same run through vesica-simulate --level 0.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TestData.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/SphereMesh.h"

using namespace vesica;
using namespace vesica::simulate;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A sphere of `ml` with its south cap as the outlet; level 0 uses only its volume and
// thickness.
WallModel reference_sphere(double ml, double H) {
  const double R = std::cbrt(3.0 * units::m3_from_ml(ml) / (4.0 * kPi));
  WallModel wall = sphere_wall(R, H, 8);
  fix_sphere_rigid_modes(wall);
  return wall;
}

RunOptions level0() {
  RunOptions o;
  o.level = 0;
  return o;
}

// Pdet (cmH2O) at volume V (ml) on the rows of a history, interpolated; rows from `from` on.
double pdet_at(const std::vector<HistoryRow>& rows, double V, std::size_t from, bool falling) {
  for (std::size_t i = from + 1; i < rows.size(); ++i) {
    const HistoryRow &a = rows[i - 1], &b = rows[i];
    if ((falling && a.volume_ml >= V && b.volume_ml <= V) ||
        (!falling && a.volume_ml <= V && b.volume_ml >= V)) {
      const double t = (V - a.volume_ml) / (b.volume_ml - a.volume_ml);
      return a.pdet_cmh2o + t * (b.pdet_cmh2o - a.pdet_cmh2o);
    }
  }
  return NAN;
}

}  // namespace

TEST(LumpedCavity, FollowsTheBalloonPastItsLimitPoint) {
  const double H = 3e-3, mu = 5e3;
  const WallModel wall = reference_sphere(50.0, H);
  const double V_ref = units::ml_from_m3(enclosed_volume(wall, wall.nodes));
  ProtocolSettings p;
  p.start_ml = V_ref;
  p.capacity_ml = 4.0 * V_ref;  // λ = 4^(1/3) = 1.587, past the peak at 7^(1/6) = 1.383
  p.void_after_fill = false;
  p.gravity = false;
  const CystometryResult r =
      run_cystometry(wall, {"neo-hookean", {{"mu", mu}, {"K_per_mu", 1e3}}}, p, level0());
  ASSERT_TRUE(r.completed) << r.failure;
  const double R = units::m_from_mm(r.summary["sphere_radius_mm"].get<double>());
  EXPECT_NEAR(r.summary["sphere_thickness_mm"].get<double>(), 3.0, 1e-9);
  EXPECT_NEAR(4.0 / 3.0 * kPi * R * R * R, units::m3_from_ml(V_ref), 1e-12);
  double worst = 0.0;
  for (const HistoryRow& row : r.history) {
    const double l = std::cbrt(row.volume_ml / V_ref);
    const double analytic = units::cmh2o_from_pa(2.0 * H / R * mu * (1.0 / l - std::pow(l, -7)));
    if (l > 1.01) worst = std::max(worst, std::abs(row.pdet_cmh2o / analytic - 1.0));
  }
  std::cout << "[ lumped balloon ] " << r.history.size() << " rows to " << 4.0 * V_ref
            << " ml, worst relative deviation " << worst << std::endl;
  EXPECT_LT(worst, 0.002);  // K = 1000 mu: the wall is all but incompressible
  EXPECT_LT(r.summary["compute_s"].get<double>(), 1.0);
}

TEST(LumpedCavity, ContractingBladderObeysGriffithsBladderOutputRelation) {
  // The detrusor alone: a matrix a thousand times softer than the contraction, no fibers.
  const MaterialSpec muscle{"neo-hookean",
                            {{"mu", 100.0},
                             {"K_per_mu", 1e3},
                             {"contractility", 1e5},
                             {"optimal_stretch", 3.0},
                             {"stretch_width", 1.5},
                             {"hill_a", 0.3},
                             {"hill_vmax", 0.07}}};
  const WallModel wall = reference_sphere(20.0, 3e-3);
  ProtocolSettings p;
  p.gravity = false;
  p.activation_onset_s = 0.0;  // fully active from the start of voiding
  p.p_close_cmh2o = 0.0;
  p.urethra_half_open_cmh2o = 0.0;
  p.r2_cmh2o_s2_per_ml2 = 0.0;
  // Isovolumetric at 300 ml: the urethra never opens.
  const double V = 300.0, a = 0.3, vmax = 0.07;
  p.capacity_ml = V;
  p.p_open_cmh2o = 200.0;
  const CystometryResult iso = run_cystometry(wall, muscle, p, level0());
  const double P_iso = iso.summary["pves_max_voiding_cmh2o"].get<double>();
  const double P_passive = iso.summary["pdet_at_capacity_cmh2o"].get<double>();
  EXPECT_GT(P_iso, 20.0 * P_passive) << "the passive wall must not matter here";
  // Voiding from 350 ml through ever less resistant urethras: at 300 ml, faster flow,
  // lower pressure.
  p.capacity_ml = 350.0;
  p.p_open_cmh2o = 0.0;
  double last_pressure = P_iso;
  for (double r1 : {4.0, 2.0, 1.0, 0.5}) {
    p.r1_cmh2o_s_per_ml = r1;
    const CystometryResult r = run_cystometry(wall, muscle, p, level0());
    ASSERT_TRUE(r.completed) << r.failure;
    const double P = pdet_at(r.history, V, 0, true);
    const double Q = P / r1;  // the rigid linear urethra from p_close = 0
    const double v = Q / (3.0 * V);
    // Griffiths' hyperbola on the active part of the pressure.
    const double Pa = P - P_passive, Pa_iso = P_iso - P_passive;
    const double lhs = (Pa + a * Pa_iso) * (v + a * vmax), rhs = (Pa_iso + a * Pa_iso) * a * vmax;
    std::cout << "[ output relation ] R1 " << r1 << ": Q " << Q << " ml/s, Pdet " << P
              << " cmH2O (isovolumetric " << P_iso << "), (P + a)(v + b) / ((P0 + a) b) "
              << lhs / rhs << std::endl;
    EXPECT_NEAR(lhs / rhs, 1.0, 0.03) << "R1 = " << r1;
    EXPECT_LT(P, last_pressure) << "R1 = " << r1;
    last_pressure = P;
  }
}

TEST(LumpedCavity, RunsFromTheCommandLineAsLevelZero) {
  const std::filesystem::path dir = vesica::test::scratch_dir("simulate-level0-cli");
  const std::string bin = vesica::test::bin_dir().string();
  auto r = vesica::test::run_command(bin + "/vesica-surface --shape sphere --volume-ml 50 -o " +
                                     (dir / "s.vtp").string() + " --edge-mm 8 --outlet auto");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = vesica::test::run_command(bin + "/vesica-mesh " + (dir / "s.vtp").string() + " -o " +
                                (dir / "s.msh").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = vesica::test::run_command(bin + "/vesica-simulate " + (dir / "s.vtu").string() + " -o " +
                                (dir / "sim").string() + " --level 0 --no-series");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto s = nlohmann::json::parse(std::ifstream(dir / "sim" / "summary.json"));
  EXPECT_EQ(s["level"].get<int>(), 0);
  EXPECT_TRUE(s["completed"].get<bool>());
  EXPECT_EQ(s["voiding_drive"], "detrusor");
  EXPECT_GT(s["voided_ml"].get<double>(), 300.0);
}

// A patient who strains while her detrusor voids: with her recorded Pabd replayed, Pves
// rises by exactly that Pabd while the urethra is closed and the detrusor's Pdet is the one
// of a resting abdomen (the same wall, activation and volume), the abdomen opening the
// urethra when Pdet + Pabd reaches p_open.
TEST(LumpedCavity, RecordedStrainingWhileVoidingAddsToPvesNotToPdet) {
  const WallModel wall = reference_sphere(20.0, 3e-3);
  ProtocolSettings rest;
  rest.gravity = false;
  rest.pabd_cmh2o = 9.0;
  rest.p_open_cmh2o = 300.0;  // isovolumetric: the urethra stays closed
  rest.activation_onset_s = 5.0;
  rest.max_void_s = 20.0;
  ProtocolSettings strains = rest;
  // Hand-made trace: 9 cmH2O at capacity, 25 at 10 s, back to 12 at 20 s.
  strains.voiding_pabd = {{0.0, 10.0, 20.0}, {9.0, 25.0, 12.0}};
  const MaterialSpec bladder{"bladder", {}};
  const CystometryResult a = run_cystometry(wall, bladder, rest, level0());
  const CystometryResult b = run_cystometry(wall, bladder, strains, level0());
  ASSERT_TRUE(a.completed) << a.failure;
  ASSERT_TRUE(b.completed) << b.failure;
  ASSERT_EQ(a.history.size(), b.history.size());
  double t_void = 0.0;  // the end of filling: the first row at capacity
  for (const HistoryRow& row : a.history)
    if (row.volume_ml >= rest.capacity_ml - 1e-9) {
      t_void = row.time_s;
      break;
    }
  int compared = 0;
  for (std::size_t i = 0; i < a.history.size(); ++i) {
    const double t = b.history[i].time_s - t_void;
    const double trace = t <= 0.0    ? 9.0
                         : t <= 10.0 ? 9.0 + 1.6 * t
                                     : 25.0 - 1.3 * std::min(t - 10.0, 10.0);
    EXPECT_NEAR(b.history[i].pabd_cmh2o, trace, 1e-9) << "t = " << t;
    EXPECT_NEAR(b.history[i].pdet_cmh2o, a.history[i].pdet_cmh2o, 1e-9) << "t = " << t;
    EXPECT_NEAR(b.history[i].pves_cmh2o - a.history[i].pves_cmh2o, trace - 9.0, 1e-9);
    if (t > 0.0) ++compared;
  }
  EXPECT_GT(compared, 5);
  EXPECT_EQ(b.summary["voiding_pabd"], "recorded");
  EXPECT_EQ(a.summary["voiding_pabd"], "resting");
  // Opened by the abdomen: the resting run's Pves peaks below 70 cmH2O (asserted), the
  // straining one's above it.
  rest.p_open_cmh2o = strains.p_open_cmh2o = 70.0;
  rest.p_close_cmh2o = strains.p_close_cmh2o = 10.0;
  const CystometryResult c = run_cystometry(wall, bladder, rest, level0());
  const CystometryResult d = run_cystometry(wall, bladder, strains, level0());
  EXPECT_LT(c.summary["pves_max_voiding_cmh2o"].get<double>(), 70.0);
  EXPECT_EQ(c.summary["voiding_drive"], "none");
  EXPECT_EQ(d.summary["voiding_drive"], "detrusor");
  EXPECT_GT(d.summary["voided_ml"].get<double>(), 10.0);
}
