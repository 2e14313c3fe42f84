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
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "ShellCommand.h"
#include "TestData.h"
#include "cavity/HydrostaticCavity.h"
#include "cavity/LevelLadder.h"
#include "fluid/NavierStokesCavity.h"
#include "protocol/CystometryProtocol.h"
#include "vesica/core/Units.h"
#include "vesica/simulate/fluid/FluidMesh.h"
#include "vesica/simulate/materials/MaterialRegistry.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/MeshReader.h"
#include "vesica/simulate/wall/SphereMesh.h"
#include "vesica/simulate/wall/WallLoading.h"

using namespace vesica;
using namespace vesica::simulate;

namespace {

// A model of any level whose voiding steps fail (as a chattering tension field does) once
// the volume has fallen below fail_below_m3, so that the protocol hands its voiding down;
// otherwise the model it stands for, whole.
class FailingModel final : public CavityModel {
 public:
  FailingModel(CavityModel& model, double fail_below_m3) : m_(model), fail_below_(fail_below_m3) {}
  FailingModel(std::unique_ptr<CavityModel> owned, double fail_below_m3)
      : owned_(std::move(owned)), m_(*owned_), fail_below_(fail_below_m3) {}

  StepRules rules() const override { return m_.rules(); }
  bool needs_settling(double v) const override { return m_.needs_settling(v); }
  StepResult try_volume_step(double v, const ProtocolLoads& l) override {
    return m_.try_volume_step(v, l);
  }
  void start_clock() override { m_.start_clock(); }
  void urethra_opens(const UrethraLaw& u) override { m_.urethra_opens(u); }
  StepResult try_step(const StepRequest& step) override {
    if (step.urethra && m_.volume() < fail_below_) {
      StepResult r;
      r.failure = "no convergence (made to fail by the test)";
      return r;
    }
    return m_.try_step(step);
  }
  int level() const override { return m_.level(); }
  CarriedState carried_state() const override { return m_.carried_state(); }
  std::string voiding_end_note(const std::string& f) const override {
    return m_.voiding_end_note(f);
  }
  double volume() const override { return m_.volume(); }
  double pves() const override { return m_.pves(); }
  double outflow() const override { return m_.outflow(); }
  double reference_volume() const override { return m_.reference_volume(); }
  const WallModel& wall() const override { return m_.wall(); }
  std::vector<Eigen::Vector3d> wall_positions() const override { return m_.wall_positions(); }
  std::vector<MembraneStressOutput> wall_stresses() const override { return m_.wall_stresses(); }
  nlohmann::json statistics() const override { return m_.statistics(); }
  void add_summary(nlohmann::json& s) const override { m_.add_summary(s); }
  void add_frame(double t, bool write) override { m_.add_frame(t, write); }
  void finish_frames() override { m_.finish_frames(); }
  std::vector<std::string> take_notes() override { return m_.take_notes(); }
  std::string progress_label() const override { return m_.progress_label(); }

 private:
  std::unique_ptr<CavityModel> owned_;
  CavityModel& m_;
  double fail_below_;
};

// The ladder of levels, whose level 1 fails in turn below fail_below_m3.
class LadderFailingAtLevelOne final : public LevelLadder {
 public:
  LadderFailingAtLevelOne(const WallModel& wall, const Material& material,
                          const ProtocolSettings& settings, const RunOptions& options,
                          double fail_below_m3)
      : LevelLadder(wall, material, settings, options), fail_below_(fail_below_m3) {}
  Step below(const CavityModel& from, const std::string& failure) const override {
    Step step = LevelLadder::below(from, failure);
    if (step.model && step.model->level() == 1)
      step.model = std::make_unique<FailingModel>(std::move(step.model), fail_below_);
    return step;
  }

 private:
  double fail_below_;
};

// V = V_start + infused − voided on every row (continuity, through every hand-over).
void expect_mass_balance(const CystometryResult& r) {
  const double start = r.history.front().volume_ml;
  for (const HistoryRow& row : r.history)
    EXPECT_NEAR(row.volume_ml, start + row.infused_ml - row.voided_ml, 1e-6 * start)
        << "t = " << row.time_s;
}

// Whether a history row stands where the hand-over says it happened.
bool a_row_is_at(const CystometryResult& r, const LevelHandOver& h) {
  return std::any_of(r.history.begin(), r.history.end(), [&](const HistoryRow& row) {
    return row.time_s == h.time_s && row.volume_ml == h.volume_ml;
  });
}

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

// The default wall on the sphere at level 1, its voiding steps made to fail below 175 ml,
// run by the protocol with the ladder of levels under options o.
CystometryResult run_wall_failing_below_175_ml(const RunOptions& o) {
  const WallModel wall = sphere();
  const ProtocolSettings p = protocol();
  const std::unique_ptr<Material> material = make_material({"bladder", {}});
  HydrostaticCavity cavity(wall, *material, p, o);
  FailingModel failing(cavity, units::m3_from_ml(175.0));
  const LevelLadder ladder(wall, *material, p, o);
  return CystometryProtocol(p, o).run(failing, &ladder);
}

}  // namespace

TEST(VoidingTail, AWallThatCannotGoOnIsContinuedByItsSphereEquivalent) {
  const WallModel wall = sphere();
  const ProtocolSettings p = protocol();
  RunOptions o;
  o.hand_over = true;  // the fallback, off by default
  const CystometryResult whole = run_cystometry(wall, {"bladder", {}}, p, o);
  ASSERT_TRUE(whole.completed) << whole.failure;
  EXPECT_FALSE(whole.summary.contains("voiding_tail"));

  const CystometryResult tail = run_wall_failing_below_175_ml(o);
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
  const std::vector<LevelHandOver>& hand_overs = tail.card.hand_overs;
  ASSERT_EQ(hand_overs.size(), 1u);
  EXPECT_EQ(hand_overs[0].from, 1);
  EXPECT_EQ(hand_overs[0].to, 0);
  EXPECT_EQ(hand_overs[0].volume_ml, t["from_ml"].get<double>());
  EXPECT_TRUE(a_row_is_at(tail, hand_overs[0]));
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
  expect_mass_balance(tail);

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

// The fallback is labelled and off by default (--hand-over turns it on): the void then ends
// where the wall stopped, with a note, and the card says no hand-over was allowed.
TEST(VoidingTail, WithTheHandOverOffTheVoidEndsWhereTheWallStopped) {
  const RunOptions o;
  EXPECT_FALSE(o.hand_over);
  const CystometryResult r = run_wall_failing_below_175_ml(o);
  ASSERT_TRUE(r.completed) << r.failure;
  EXPECT_TRUE(r.card.hand_overs.empty());
  EXPECT_FALSE(r.summary.contains("voiding_tail"));
  // The last row is where the wall stopped: the first below 175 ml, and what is left.
  const HistoryRow& last = r.history.back();
  EXPECT_LT(last.volume_ml, 175.0);
  EXPECT_GT(last.volume_ml, 150.0);
  EXPECT_NEAR(r.summary["pvr_ml"].get<double>(), last.volume_ml, 1e-6);
  ASSERT_TRUE(r.summary.contains("notes"));
  EXPECT_NE(r.summary["notes"].dump().find("hand-over to a simpler level being off"),
            std::string::npos)
      << r.summary["notes"];
  expect_mass_balance(r);
}

// The protocol alone decides a hand-over, whatever level the run started at: a level-2 run
// whose Navier–Stokes voiding is made to fail below 100 ml goes on at level 1, whose wall is
// made to fail below 80 ml in turn and goes on at level 0, each from the state of the level
// above. Checked against truths outside the ladder: continuity on every row, and the void
// of an uninterrupted level-1 run of the same wall (a sphere, on which level 0 is the
// wall's own answer and level 2's urine adds little: the same voided volume and PVR within
// 2 ml).
TEST(VoidingTail, AVoidHandedDownTwoLevelsFromLevelTwoEndsLikeALevelOneRun) {
  namespace fs = std::filesystem;
  const fs::path dir = test::scratch_dir("voiding_tail_from_level_two");
  const std::string bin = test::bin_dir().string();
  test::CommandResult c =
      test::run_command(bin + "/vesica-surface -o " + (dir / "sphere.vtp").string() +
                        " --shape sphere --volume-ml 50 --edge-mm 8 --outlet auto --json");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  c = test::run_command(bin + "/vesica-mesh " + (dir / "sphere.vtp").string() + " -o " +
                        (dir / "sphere.msh").string() + " --fluid --json");
  ASSERT_EQ(c.exit_code, 0) << c.output;
  const WallModel wall = load_wall(dir / "sphere.vtu", WallOptions{});
  const fluid::FluidMesh urine = read_urine(dir / "sphere.vtu");
  ProtocolSettings p;
  p.capacity_ml = 120.0;

  const CystometryResult level1 = run_cystometry(wall, {"bladder", {}}, p, RunOptions{});
  ASSERT_TRUE(level1.completed) << level1.failure;
  EXPECT_TRUE(level1.card.hand_overs.empty());

  RunOptions o;
  o.level = 2;
  o.hand_over = true;  // the fallback, off by default
  const std::unique_ptr<Material> material = make_material({"bladder", {}});
  fluid::NavierStokesCavity navier_stokes(wall, fluid::reference_urine(urine, wall), *material, p,
                                          o);
  FailingModel failing(navier_stokes, units::m3_from_ml(100.0));
  const LadderFailingAtLevelOne ladder(wall, *material, p, o, units::m3_from_ml(80.0));
  const CystometryResult r = CystometryProtocol(p, o).run(failing, &ladder);
  ASSERT_TRUE(r.completed) << r.failure;

  const std::vector<LevelHandOver>& h = r.card.hand_overs;
  ASSERT_EQ(h.size(), 2u) << r.summary["notes"];
  EXPECT_EQ(h[0].from, 2);
  EXPECT_EQ(h[0].to, 1);
  EXPECT_LT(h[0].volume_ml, 100.0);
  EXPECT_GT(h[0].volume_ml, 80.0);
  EXPECT_EQ(h[1].from, 1);
  EXPECT_EQ(h[1].to, 0);
  EXPECT_LT(h[1].volume_ml, 80.0);
  EXPECT_GT(h[0].time_s, 0.0);
  EXPECT_GT(h[1].time_s, h[0].time_s);
  for (const LevelHandOver& each : h) EXPECT_TRUE(a_row_is_at(r, each)) << each.volume_ml;
  // The summary and the solver statistics say the same.
  EXPECT_EQ(r.summary["level"], 2);
  EXPECT_EQ(r.summary["level1_from"]["volume_ml"].get<double>(), h[0].volume_ml);
  EXPECT_EQ(r.summary["voiding_tail"]["from_level"], 1);
  EXPECT_EQ(r.summary["voiding_tail"]["from_ml"].get<double>(), h[1].volume_ml);
  ASSERT_EQ(r.summary["newton"]["after_hand_over"].size(), 2u);
  EXPECT_EQ(r.summary["newton"]["after_hand_over"][0]["level"], 1);
  EXPECT_EQ(r.summary["newton"]["after_hand_over"][1]["level"], 0);
  expect_mass_balance(r);

  std::cout << "[ ladder ] hand-overs at " << h[0].volume_ml << " and " << h[1].volume_ml
            << " ml; voided " << r.summary["voided_ml"] << " vs " << level1.summary["voided_ml"]
            << " ml, PVR " << r.summary["pvr_ml"] << " vs " << level1.summary["pvr_ml"] << " ml"
            << std::endl;
  EXPECT_NEAR(r.summary["pvr_ml"].get<double>(), level1.summary["pvr_ml"].get<double>(), 2.0);
  EXPECT_NEAR(r.summary["voided_ml"].get<double>(), level1.summary["voided_ml"].get<double>(), 2.0);
}
