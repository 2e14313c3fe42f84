// An interrupted simulation continues where it stopped (issue 22 item 4): `vesica run`
// terminated with SIGTERM while vesica-simulate is filling leaves the stage "interrupted
// (checkpoint at t = … s)"; the next `vesica run` says it resumes from that checkpoint and
// ends with the history of a run that was never interrupted; and the stage is then fresh,
// as one run whole (issue 37: `--resume` is no parameter).
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "PipelineTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

// A 50 ml sphere filled to 400 ml, checkpointed after (nearly) every step, so that a
// checkpoint exists early in filling.
fs::path sphere_pipeline(const fs::path& dir) {
  write_text(dir / "p.yaml",
             "workdir: out\n"
             "stages:\n"
             "  surface: {tool: surface, output: sphere.vtp, params: {shape: sphere, volume_ml: "
             "50, edge_mm: 5}}\n"
             "  simulate: {tool: simulate, input: sphere.vtp, output: sim, params: {capacity_ml: "
             "400, no_series: true, checkpoint_minutes: 0.0001}}\n");
  return dir / "p.yaml";
}

}  // namespace

TEST(RunnerResume, ASimulationInterruptedMidFillingResumesToTheUninterruptedHistoryAndStaysFresh) {
  const fs::path whole_dir = scratch_dir("runner-resume-whole");
  const CommandResult whole =
      run_vesica("run " + quoted(sphere_pipeline(whole_dir).string()), whole_dir);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  const std::string expected = slurp(whole_dir / "out/sim/history.csv");

  const fs::path dir = scratch_dir("runner-resume");
  const fs::path file = sphere_pipeline(dir);
  const pid_t runner = start_run(file, dir / "run.err");
  const fs::path checkpoint = dir / "out/.vesica/checkpoints/simulate/checkpoint.bin";
  for (int i = 0; i < 3000 && !fs::exists(checkpoint); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(checkpoint)) << slurp(dir / "run.err");
  ::kill(runner, SIGTERM);
  EXPECT_EQ(wait_exit(runner), 128 + SIGTERM) << slurp(dir / "run.err");
  ASSERT_FALSE(fs::exists(dir / "out/sim")) << "the simulation finished before it was stopped";
  const auto status = status_of(file, dir).at("simulate");
  EXPECT_EQ(status.second.rfind("interrupted (checkpoint at t = ", 0), 0u) << status.second;

  const CommandResult resumed = run_vesica("run " + quoted(file.string()), dir);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("vesica: resuming simulate from its checkpoint at t = "),
            std::string::npos)
      << resumed.err;
  EXPECT_EQ(slurp(dir / "out/sim/history.csv"), expected);
  EXPECT_FALSE(fs::exists(checkpoint));
  EXPECT_EQ(status_of(file, dir).at("simulate").first, "fresh")
      << status_of(file, dir).at("simulate").second;
  EXPECT_TRUE(run_json(file, dir).empty());  // the next run has nothing to do
}
