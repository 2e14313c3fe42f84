// A long simulation stopped by SIGTERM continues from its checkpoint to the results an
// uninterrupted run gives (issue 22 item 4; docs/simulate.md, "Checkpoint and resume"):
// every history row equal to 1e-12 (relative) and the summary equal but for compute
// times. The run is stopped through the real signal path, injected by the test alone: in
// process, SIGTERM raised from the run's progress callback after a chosen number of rows;
// the executable, a real SIGTERM sent as soon as its first checkpoint exists (one after
// every step). A checkpoint that is corrupt or belongs to other parameters is refused with
// one line naming it, the earlier output kept.
#include <gtest/gtest.h>

#include <array>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "ShellCommand.h"
#include "TestData.h"
#include "fluid/TetQuality.h"
#include "vesica/io/HistoryCsv.h"
#include "vesica/simulate/fluid/FluidMesh.h"
#include "vesica/simulate/protocol/CheckpointFile.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/MeshReader.h"
#include "vesica/simulate/wall/SphereMesh.h"
#include "vesica/simulate/wall/WallLoading.h"

namespace fs = std::filesystem;
using namespace vesica::simulate;
using namespace vesica::test;

namespace {

// Stops a run after its k-th step past the start: SIGTERM raised from its progress
// callback, which the run calls after every history row (the first row is the settled
// start), as a user's Ctrl-C would arrive during that step.
void stop_after_steps(RunOptions& options, int k) {
  auto rows = std::make_shared<int>(0);
  options.on_progress = [rows, k](const std::string&, double) {
    if (++*rows == k + 1) std::raise(SIGTERM);
  };
}

// Runs a shell command and stops it with a real SIGTERM, as `kill` would, as soon as `file`
// exists; its exit status and output (written to `log`), as run_command gives them.
CommandResult run_stopped_once_written(const std::string& command, const fs::path& file,
                                       const fs::path& log) {
  const std::string shell = "exec " + command + " > '" + log.string() + "' 2>&1";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", shell.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  while (::waitpid(pid, &status, WNOHANG) == 0) {
    if (fs::exists(file)) {
      ::kill(pid, SIGTERM);
      ::waitpid(pid, &status, 0);
      break;
    }
    ::usleep(500);
  }
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.output = file_text(log);
  return r;
}

bool same(double a, double b) {
  return std::abs(a - b) <= 1e-12 * std::max({std::abs(a), std::abs(b), 1e-300});
}

// The eight columns of a history row, in history.csv's order.
std::array<double, 8> columns(const HistoryRow& r) {
  return {r.time_s,     r.infused_ml, r.volume_ml, r.pves_cmh2o,
          r.pabd_cmh2o, r.pdet_cmh2o, r.flow_ml_s, r.voided_ml};
}

void expect_same_rows(const std::vector<HistoryRow>& a, const std::vector<HistoryRow>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::array<double, 8> x = columns(a[i]), y = columns(b[i]);
    for (std::size_t k = 0; k < x.size(); ++k)
      EXPECT_TRUE(same(x[k], y[k]))
          << "row " << i << " column " << k << ": " << x[k] << " vs " << y[k];
  }
}

// The index of the first row in which two histories differ (beyond 1e-12 relative).
std::size_t first_different_row(const std::vector<HistoryRow>& a,
                                const std::vector<HistoryRow>& b) {
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    const std::array<double, 8> x = columns(a[i]), y = columns(b[i]);
    for (std::size_t k = 0; k < x.size(); ++k)
      if (!same(x[k], y[k])) return i;
  }
  return std::min(a.size(), b.size());
}

nlohmann::json without_compute_times(nlohmann::json summary) {
  summary.erase("compute_s");
  summary.erase("phase_compute_s");
  return summary;
}

// A 50 ml sphere of a viscoelastic wall with inertia (Maxwell history and Bossak–Newmark
// state are part of what must carry over), filled to 200 ml, held, voided.
struct SphereRun {
  WallModel wall = [] {
    WallModel w = sphere_wall(0.0229, 3e-3, 6);
    fix_sphere_rigid_modes(w);
    return w;
  }();
  MaterialSpec material{"maxwell", {{"beta1", 1.0}, {"tau1", 20.0}}};
  ProtocolSettings protocol = [] {
    ProtocolSettings p;
    p.capacity_ml = 200.0;
    p.hold_s = 20.0;
    return p;
  }();
  RunOptions options = [] {
    RunOptions o;
    o.dynamic = true;
    return o;
  }();
  CystometryResult run() const { return run_cystometry(wall, material, protocol, options); }
};

}  // namespace

TEST(Resume, ASimulationKilledMidFillingResumesToTheSameHistory) {
  SphereRun sphere;
  const CystometryResult whole = sphere.run();
  ASSERT_TRUE(whole.completed) << whole.failure;
  const fs::path dir = scratch_dir("resume-level1");
  // Stopped early in filling, late in filling, and in the hold.
  for (int k : {3, 9, 15}) {
    SCOPED_TRACE("stopped after step " + std::to_string(k));
    SphereRun resumed;
    resumed.options.checkpoints.file = dir / ("after-" + std::to_string(k)) / "checkpoint.bin";
    resumed.options.checkpoints.identity = R"({"inputs": "sphere"})";
    stop_after_steps(resumed.options, k);
    EXPECT_THROW(resumed.run(), RunInterrupted);
    resumed.options.on_progress = nullptr;
    ASSERT_TRUE(fs::exists(resumed.options.checkpoints.file));
    resumed.options.checkpoints.resume = true;
    const CystometryResult continued = resumed.run();
    ASSERT_TRUE(continued.completed) << continued.failure;
    expect_same_rows(whole.history, continued.history);
    EXPECT_EQ(without_compute_times(whole.summary), without_compute_times(continued.summary));
  }
}

namespace {

// The command-line runs on one 50 ml sphere: an uninterrupted one, and helpers for the rest.
struct CliRuns {
  fs::path dir;
  std::string bin = bin_dir().string();
  std::string mesh;
  explicit CliRuns(const std::string& name) : dir(scratch_dir(name)) {
    CommandResult r = run_command(bin + "/vesica-surface -o " + (dir / "sphere.vtp").string() +
                                  " --shape sphere --volume-ml 50 --edge-mm 8 --json");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    mesh = (dir / "sphere.vtp").string();
  }
  std::string command(const std::string& output, const std::string& extra, bool series) const {
    return "timeout 120 " + bin + "/vesica-simulate " + mesh + " -o " + (dir / output).string() +
           " --capacity-ml 200 " + (series ? "" : "--no-series ") + extra;
  }
  CommandResult simulate(const std::string& output, const std::string& extra,
                         bool series = false) const {
    return run_command(command(output, extra, series) + " 2>&1");
  }
  // Stopped by SIGTERM at its first checkpoint (one after every step: it is still filling).
  CommandResult stopped(const std::string& output, bool series = false) const {
    return run_stopped_once_written(command(output, "--checkpoint-minutes 1e-9", series),
                                    checkpoint(output), dir / (output + ".log"));
  }
  fs::path checkpoint(const std::string& output) const {
    return dir / ".vesica" / "checkpoints" / output / "checkpoint.bin";
  }
};

int lines(const std::string& text) {
  return static_cast<int>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace

TEST(Resume, AKilledRunExitsWithTheSignalsStatusAndResumesOnTheCommandLine) {
  CliRuns cli("resume-cli");
  ASSERT_EQ(cli.simulate("whole", "", true).exit_code, 0);
  const CommandResult stopped = cli.stopped("resumed", true);
  EXPECT_EQ(stopped.exit_code, 128 + 15) << stopped.output;  // SIGTERM's conventional status
  EXPECT_FALSE(fs::exists(cli.dir / "resumed")) << "an interrupted run wrote its output";
  ASSERT_TRUE(fs::exists(cli.checkpoint("resumed"))) << stopped.output;
  const CommandResult resumed = cli.simulate("resumed", "--resume", true);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(file_text(cli.dir / "whole" / "history.csv"),
            file_text(cli.dir / "resumed" / "history.csv"));
  // The wall's frames: those before the checkpoint were kept beside it and put back.
  EXPECT_EQ(file_text(cli.dir / "whole" / "series.pvd"),
            file_text(cli.dir / "resumed" / "series.pvd"));
  int frames = 0;
  for (const auto& frame : fs::directory_iterator(cli.dir / "whole" / "series")) {
    ++frames;
    EXPECT_EQ(file_text(frame.path()),
              file_text(cli.dir / "resumed" / "series" / frame.path().filename()))
        << frame.path().filename();
  }
  EXPECT_GT(frames, 2);
  EXPECT_FALSE(fs::exists(cli.checkpoint("resumed"))) << "a finished run keeps its checkpoint";
}

TEST(Resume, AStopInTheMiddleOfAStepCheckpointsTheLastCompletedStep) {
  // A SIGTERM at the 30th factorisation (tests/support/StopAfterFactorizations.c,
  // preloaded), inside a filling step (the tangent is reused within and across filling
  // steps, so there are fewer factorisations than iterations, and the 30th, after the settling,
  // comes before voiding begins): the run stops there (not at the end of the step), its checkpoint
  // is the step before, and the run resumed from it is the run never stopped (a batch scheduler's
  // SIGTERM).
  CliRuns cli("resume-mid-step");
  ASSERT_EQ(cli.simulate("whole", "").exit_code, 0);
  const CommandResult stopped =
      run_command("LD_PRELOAD='" VESICA_STOP_AFTER_FACTORIZATIONS_LIBRARY
                  "' VESICA_TEST_STOP_AFTER_FACTORIZATIONS=30 timeout 120 " +
                  cli.bin + "/vesica-simulate " + cli.mesh + " -o " +
                  (cli.dir / "resumed").string() + " --capacity-ml 200 --no-series 2>&1");
  EXPECT_EQ(stopped.exit_code, 128 + 15) << stopped.output;
  EXPECT_NE(stopped.output.find("interrupted by SIGTERM; checkpoint at t = "), std::string::npos)
      << stopped.output;
  ASSERT_TRUE(fs::exists(cli.checkpoint("resumed"))) << stopped.output;
  // The checkpoint's time is a row of the uninterrupted history: a completed step.
  const auto identity = vesica::simulate::read_checkpoint(cli.checkpoint("resumed")).identity;
  const double t = identity["time_s"].get<double>();
  const std::vector<HistoryRow> whole =
      vesica::io::history_rows(vesica::io::read_history_csv(cli.dir / "whole" / "history.csv"));
  EXPECT_TRUE(std::any_of(whole.begin(), whole.end(),
                          [&](const HistoryRow& r) { return same(r.time_s, t); }))
      << "t = " << t;
  const CommandResult resumed = cli.simulate("resumed", "--resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
  EXPECT_EQ(file_text(cli.dir / "whole" / "history.csv"),
            file_text(cli.dir / "resumed" / "history.csv"));
}

TEST(Resume, ACorruptCheckpointIsRefusedWithOneLineAndTheEarlierOutputKept) {
  CliRuns cli("resume-corrupt");
  ASSERT_EQ(cli.simulate("out", "").exit_code, 0);
  const std::string earlier = file_text(cli.dir / "out" / "history.csv");
  ASSERT_EQ(cli.stopped("out").exit_code, 143);
  EXPECT_EQ(file_text(cli.dir / "out" / "history.csv"), earlier);
  const fs::path checkpoint = cli.checkpoint("out");
  std::string bytes = file_text(checkpoint);
  ASSERT_GT(bytes.size(), 1000u);
  {  // one flipped byte in the middle of the state
    bytes[bytes.size() / 2] ^= 0x20;
    std::ofstream(checkpoint, std::ios::binary) << bytes;
  }
  CommandResult r = cli.simulate("out", "--resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find(checkpoint.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("checksum"), std::string::npos) << r.output;
  {  // truncated
    std::ofstream(checkpoint, std::ios::binary) << bytes.substr(0, bytes.size() / 3);
  }
  r = cli.simulate("out", "--resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find(checkpoint.string()), std::string::npos) << r.output;
  {  // not a checkpoint at all
    std::ofstream(checkpoint, std::ios::binary) << "time_s,volume_ml\n0,50\n";
  }
  r = cli.simulate("out", "--resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("not a vesica checkpoint"), std::string::npos) << r.output;
  EXPECT_EQ(file_text(cli.dir / "out" / "history.csv"), earlier);
}

TEST(Resume, ACheckpointOfOtherParametersIsRefused) {
  CliRuns cli("resume-other-parameters");
  ASSERT_EQ(cli.stopped("out").exit_code, 143);
  const CommandResult r = cli.simulate("out", "--fill-rate-ml-min 40 --resume");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(lines(r.output), 1) << r.output;
  EXPECT_NE(r.output.find("other parameters"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(cli.dir / "out"));
}

namespace {

// Every number of two summaries equal to 1e-12 (relative), but for compute times, the
// solvers' work (a resumed run factorizes once more where it starts) and the mass-balance
// error, itself round-off (both within the 1e-9 of issue 22).
void expect_same_summary(const nlohmann::json& a, const nlohmann::json& b,
                         const std::string& where = "") {
  static const std::set<std::string> skipped = {"compute_s", "phase_compute_s", "timings_s",
                                                "newton", "mass_balance_error_max_rel"};
  if (a.contains("mass_balance_error_max_rel")) {
    EXPECT_LE(a["mass_balance_error_max_rel"].get<double>(), 1e-9);
    EXPECT_LE(b["mass_balance_error_max_rel"].get<double>(), 1e-9);
  }
  if (a.is_object()) {
    ASSERT_TRUE(b.is_object()) << where;
    for (const auto& [key, value] : a.items()) {
      if (skipped.count(key)) continue;
      ASSERT_TRUE(b.contains(key)) << where + "/" + key;
      expect_same_summary(value, b[key], where + "/" + key);
    }
  } else if (a.is_number_float()) {
    EXPECT_TRUE(same(a.get<double>(), b.get<double>())) << where << ": " << a << " vs " << b;
  } else {
    EXPECT_EQ(a, b) << where;
  }
}

// The level-2 input: a 50 ml sphere with its outlet patch and urine tetrahedra, filled to
// 120 ml, held 5 s and voided in process (the executable's stop and resume are the
// level-1 tests'; the checkpoint is the same file at both levels).
struct LevelTwoRuns {
  fs::path dir;
  WallModel wall;
  fluid::FluidMesh urine;
  MaterialSpec material{"bladder", {}};
  ProtocolSettings protocol = [] {
    ProtocolSettings p;
    p.capacity_ml = 120.0;
    p.hold_s = 5.0;
    return p;
  }();
  explicit LevelTwoRuns(const std::string& name) : dir(scratch_dir(name)) {
    const std::string bin = bin_dir().string();
    CommandResult r =
        run_command(bin + "/vesica-surface -o " + (dir / "sphere.vtp").string() +
                    " --shape sphere --volume-ml 50 --edge-mm 8 --outlet auto --json");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    r = run_command(bin + "/vesica-mesh " + (dir / "sphere.vtp").string() + " -o " +
                    (dir / "sphere.msh").string() + " --fluid --json");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    wall = load_wall(dir / "sphere.vtu", WallOptions{});
    urine = read_urine(dir / "sphere.vtu");
  }
  static RunOptions options() {
    RunOptions o;
    o.level = 2;
    return o;
  }
  CystometryResult run(const RunOptions& o) const {
    return run_cystometry(wall, material, protocol, o, &urine);
  }
  // The run of `o` stopped by SIGTERM after `steps` steps (its checkpoint in `folder`),
  // then resumed from its checkpoint.
  CystometryResult stopped_and_resumed(RunOptions o, const std::string& folder, int steps) const {
    o.checkpoints.file = dir / folder / "checkpoint.bin";
    o.checkpoints.identity = R"({"inputs": "sphere"})";
    stop_after_steps(o, steps);
    EXPECT_THROW(run(o), RunInterrupted);
    o.on_progress = nullptr;
    o.checkpoints.resume = true;
    return run(o);
  }
};

}  // namespace

TEST(Resume, ALevelTwoSimulationKilledMidFillingResumesToTheSameHistory) {
  const LevelTwoRuns runs("resume-level2");
  const CystometryResult whole = runs.run(runs.options());
  ASSERT_TRUE(whole.completed) << whole.failure;
  const CystometryResult resumed = runs.stopped_and_resumed(runs.options(), "stopped", 20);
  ASSERT_TRUE(resumed.completed) << resumed.failure;
  expect_same_rows(whole.history, resumed.history);
  expect_same_summary(whole.summary, resumed.summary);
}

// The checkpoint holds the rebuilt tetrahedra (and the state moved onto them), not the
// mesh read: a run stopped after a remesh continues on the same tetrahedra. The urine is
// remeshed early: its threshold set just under the quality of the tetrahedra read, so that
// the first step that lowers their quality at all rebuilds them.
TEST(Resume, ALevelTwoSimulationResumedAfterARemeshEndsTheSame) {
  const LevelTwoRuns runs("resume-level2-remesh");
  const double read_quality =
      fluid::min_radius_ratio(runs.urine.nodes, runs.urine.nodes, runs.urine.tets);
  RunOptions early = runs.options();
  early.level2.remesh_radius_ratio = (1.0 - 1e-9) * read_quality;
  const CystometryResult whole = runs.run(early);
  ASSERT_TRUE(whole.completed) << whole.failure;
  ASSERT_GE(whole.summary["remeshes"].get<int>(), 1);
  // The stop below comes after a remesh: the history leaves the one on the tetrahedra read
  // before the row it is stopped at.
  const CystometryResult unremeshed = runs.run(runs.options());
  EXPECT_LE(first_different_row(whole.history, unremeshed.history), 20u);
  const CystometryResult resumed = runs.stopped_and_resumed(early, "stopped", 20);
  ASSERT_TRUE(resumed.completed) << resumed.failure;
  expect_same_rows(whole.history, resumed.history);
  expect_same_summary(whole.summary, resumed.summary);
}
