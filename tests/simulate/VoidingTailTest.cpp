// The tail of voiding (docs/simulate.md, "The tail of voiding"): when the wall cannot take
// a voiding step, the rest of voiding runs on its sphere-equivalent (level 0) from the
// wall's state. On a sphere the sphere-equivalent is the wall's own answer (level 0 within
// 2 % of level 1's Pdet, Physiology.LumpedModelMatchesTheMembraneOnASphere), so a run whose
// wall is made to fail halfway through voiding must continue the wall-only run:
//  - the pressure scale at the hand-over is the sphere's shape factor, 1 within 3 %;
//  - Pdet does not jump at the hand-over (within 3 % of the wall's);
//  - the voided volume, PVR and Qmax of the wall-only run are reached (2 ml, 3 %);
//  - V = V_start + infused − voided on every row, before and after the hand-over;
//  - the note and the summary's "voiding_tail" say where the wall handed over.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <memory>
#include <string>

#include "cavity/HydrostaticCavity.h"
#include "protocol/CystometryProtocol.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/SphereMesh.h"

using namespace vesica;
using namespace vesica::simulate;

namespace {

// The level-1 wall, whose voiding steps fail (as a chattering tension field does) once
// the volume has fallen below fail_below_m3, until the wall hands its voiding over.
class FailingWall final : public CavityModel {
 public:
  FailingWall(HydrostaticCavity& wall, double fail_below_m3)
      : wall_(wall), fail_below_(fail_below_m3) {}

  StepRules rules() const override { return wall_.rules(); }
  bool needs_settling(double v) const override { return wall_.needs_settling(v); }
  StepResult try_volume_step(double v, const ProtocolLoads& l) override {
    return wall_.try_volume_step(v, l);
  }
  void start_clock() override { wall_.start_clock(); }
  void urethra_opens(const UrethraLaw& u) override { wall_.urethra_opens(u); }
  StepResult try_step(const StepRequest& step) override {
    if (!handed_over_ && step.urethra && wall_.volume() < fail_below_) {
      StepResult r;
      r.failure = "no convergence (made to fail by the test)";
      return r;
    }
    return wall_.try_step(step);
  }
  bool hand_over_voiding(const std::string& failure, double time_s) override {
    handed_over_ = wall_.hand_over_voiding(failure, time_s);
    return handed_over_;
  }
  double volume() const override { return wall_.volume(); }
  double pves() const override { return wall_.pves(); }
  double outflow() const override { return wall_.outflow(); }
  double reference_volume() const override { return wall_.reference_volume(); }
  const WallModel& wall() const override { return wall_.wall(); }
  std::vector<Eigen::Vector3d> wall_positions() const override { return wall_.wall_positions(); }
  std::vector<MembraneStressOutput> wall_stresses() const override { return wall_.wall_stresses(); }
  nlohmann::json statistics() const override { return wall_.statistics(); }
  void add_summary(nlohmann::json& s) const override { wall_.add_summary(s); }
  std::vector<std::string> take_notes() override { return wall_.take_notes(); }
  std::vector<LevelHandOver> hand_overs() const override { return wall_.hand_overs(); }

 private:
  HydrostaticCavity& wall_;
  double fail_below_;
  bool handed_over_ = false;
};

// The default bladder wall as a 20 ml sphere (its stress-free volume), held only against
// rigid motion, without gravity: a wall that stays a sphere (as in PhysiologyTest).
WallModel sphere() {
  const double R = std::cbrt(3.0 * units::m3_from_ml(20.0) / (4.0 * 3.14159265358979));
  WallModel wall = sphere_wall(R, 3e-3, 10);
  fix_sphere_rigid_modes(wall);
  return wall;
}

ProtocolSettings protocol() {
  ProtocolSettings p;
  p.gravity = false;
  return p;
}

}  // namespace

TEST(VoidingTail, AWallThatCannotGoOnIsContinuedByItsSphereEquivalent) {
  const WallModel wall = sphere();
  const ProtocolSettings p = protocol();
  const RunOptions o;
  const CystometryResult whole = run_cystometry(wall, {"bladder", {}}, p, o);
  ASSERT_TRUE(whole.completed) << whole.failure;
  EXPECT_FALSE(whole.summary.contains("voiding_tail"));

  const std::unique_ptr<Material> material = make_material({"bladder", {}});
  HydrostaticCavity cavity(wall, *material, p, o);
  FailingWall failing(cavity, units::m3_from_ml(175.0));
  const CystometryResult tail = CystometryProtocol(p, o).run(failing);
  ASSERT_TRUE(tail.completed) << tail.failure;

  ASSERT_TRUE(tail.summary.contains("voiding_tail")) << tail.summary.dump(1);
  const auto& t = tail.summary["voiding_tail"];
  EXPECT_NEAR(t["pressure_scale"].get<double>(), 1.0, 0.03);
  EXPECT_LT(t["from_ml"].get<double>(), 175.0);
  EXPECT_GT(t["from_ml"].get<double>(), 150.0);
  ASSERT_TRUE(tail.summary.contains("notes"));
  EXPECT_NE(tail.summary["notes"].dump().find("sphere-equivalent (level 0)"), std::string::npos)
      << tail.summary["notes"];

  // The model card's hand-over is the same one: level 1 to 0 where the wall stopped, at the
  // time of its last row.
  const std::vector<LevelHandOver> hand_overs = failing.hand_overs();
  ASSERT_EQ(hand_overs.size(), 1u);
  EXPECT_EQ(hand_overs[0].from, 1);
  EXPECT_EQ(hand_overs[0].to, 0);
  EXPECT_EQ(hand_overs[0].volume_ml, t["from_ml"].get<double>());
  EXPECT_TRUE(std::any_of(tail.history.begin(), tail.history.end(), [&](const HistoryRow& r) {
    return r.time_s == hand_overs[0].time_s && r.volume_ml == hand_overs[0].volume_ml;
  }));
  EXPECT_NE(hand_overs[0].reason.find("could not take a voiding step"), std::string::npos);

  // Pdet across the hand-over: the last wall row and the first tail row, one step apart.
  const double from = t["from_ml"].get<double>();
  for (std::size_t i = 1; i < tail.history.size(); ++i) {
    const HistoryRow &a = tail.history[i - 1], &b = tail.history[i];
    if (a.volume_ml == from && b.volume_ml < from) {
      std::cout << "[ tail ] Pdet " << a.pdet_cmh2o << " -> " << b.pdet_cmh2o << " cmH2O at "
                << from << " ml" << std::endl;
      EXPECT_NEAR(b.pdet_cmh2o, a.pdet_cmh2o, 0.03 * a.pdet_cmh2o);
    }
  }
  const double start = tail.history.front().volume_ml;
  for (const HistoryRow& row : tail.history)
    EXPECT_NEAR(row.volume_ml, start + row.infused_ml - row.voided_ml, 1e-6 * start)
        << "t = " << row.time_s;

  std::cout << "[ tail ] voided " << tail.summary["voided_ml"] << " vs "
            << whole.summary["voided_ml"] << " ml, Qmax " << tail.summary["qmax_ml_s"] << " vs "
            << whole.summary["qmax_ml_s"] << " ml/s, PVR " << tail.summary["pvr_ml"] << " vs "
            << whole.summary["pvr_ml"] << " ml" << std::endl;
  EXPECT_NEAR(tail.summary["voided_ml"].get<double>(), whole.summary["voided_ml"].get<double>(),
              2.0);
  EXPECT_NEAR(tail.summary["pvr_ml"].get<double>(), whole.summary["pvr_ml"].get<double>(), 2.0);
  EXPECT_NEAR(tail.summary["qmax_ml_s"].get<double>(), whole.summary["qmax_ml_s"].get<double>(),
              0.03 * whole.summary["qmax_ml_s"].get<double>());
}
