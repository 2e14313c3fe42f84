// The runner as a process among others: one run at a time per workdir, signals passed on
// to the running stage, the stage's own progress shown on a terminal, status as an exit
// code, and a file saved by hand after a stage failed kept as an edit.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <regex>
#include <thread>

#include "PipelineTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

// a -> b, b sleeping or reporting progress as told.
fs::path two_stages(const fs::path& dir, const std::string& b_params) {
  write_text(dir / "p.yaml",
             "workdir: out\n"
             "stages:\n"
             "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
             "  b: {tool: teststage, input: a.txt, output: b.txt, params: {" +
                 b_params + "}}\n");
  return dir / "p.yaml";
}

// Whether a process whose command line contains `text` is running. "[x]yz" matches "xyz"
// but not the shell running pgrep, whose command line holds "[x]yz".
bool process_running(const std::string& text, const fs::path& scratch) {
  return run_command("pgrep -f " + quoted("[" + text.substr(0, 1) + "]" + text.substr(1)), scratch)
             .exit_code == 0;
}

void wait_for_file(const fs::path& p) {
  for (int i = 0; i < 100 && !fs::exists(p); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
}

// `vesica run` started in the background on a -> b where b sleeps (its label names the
// process); returns once b is running.
struct SleepingRun {
  fs::path dir, file;
  pid_t runner;
  SleepingRun(const std::string& name, const std::string& label) : dir(scratch_dir(name)) {
    file = two_stages(dir, "label: " + label + ", sleep_ms: 30000");
    runner = start_run(file, dir / "run.err");
    wait_for_file(dir / "out/.vesica/b.failed.json");
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
  }
};

}  // namespace

TEST(RunnerProcess, ASecondRunWaitsForTheFirstAndSaysWhichProcessHoldsTheWorkdir) {
  const fs::path dir = scratch_dir("runner-lock");
  const fs::path file = two_stages(dir, "label: B, sleep_ms: 1500");
  const pid_t first = start_run(file, dir / "first.err");
  wait_for_file(dir / "out/.vesica/b.failed.json");  // b is running
  const CommandResult second = run_vesica("run " + quoted(file.string()), dir);
  EXPECT_EQ(wait_exit(first), 0);
  EXPECT_EQ(second.exit_code, 0) << second.err;
  EXPECT_NE(
      second.err.find("vesica: waiting for PID " + std::to_string(first) + ", which is working in"),
      std::string::npos)
      << second.err;
  // It decided what to run after the first had finished: nothing.
  EXPECT_NE(second.err.find("nothing to do, 2 stages are fresh"), std::string::npos) << second.err;
  EXPECT_EQ(slurp(dir / "out/b.txt"), "A\nB\n");
}

TEST(RunnerProcess, TerminatingTheRunnerStopsItsStageAndSaysWhatWasInterrupted) {
  const SleepingRun r("runner-sigterm", "runner-sigterm-stage");
  ASSERT_TRUE(process_running("runner-sigterm-stage", r.dir));
  ::kill(r.runner, SIGTERM);  // the runner alone, as `kill PID` does
  EXPECT_EQ(wait_exit(r.runner), 128 + SIGTERM);
  EXPECT_FALSE(process_running("runner-sigterm-stage", r.dir));  // waited for
  const std::string err = slurp(r.dir / "run.err");
  EXPECT_NE(err.find("vesica: SIGTERM: stopping b, waiting for it to end"), std::string::npos)
      << err;
  EXPECT_NE(err.find("vesica: interrupted by SIGTERM: b stopped and will run again; 1 stages "
                     "finished before"),
            std::string::npos)
      << err;
  EXPECT_EQ(status_of(r.file, r.dir).at("b"),
            std::make_pair(std::string("failed"), std::string("interrupted: SIGTERM")));
}

TEST(RunnerProcess, ARunnerKilledOutrightTakesItsStageWithIt) {
  const SleepingRun r("runner-sigkill", "runner-sigkill-stage");
  ASSERT_TRUE(process_running("runner-sigkill-stage", r.dir));
  ::kill(r.runner, SIGKILL);
  EXPECT_EQ(wait_exit(r.runner), 128 + SIGKILL);
  bool gone = false;
  for (int i = 0; i < 40 && !gone; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    gone = !process_running("runner-sigkill-stage", r.dir);
  }
  EXPECT_TRUE(gone);
  EXPECT_EQ(status_of(r.file, r.dir).at("b"),
            std::make_pair(std::string("failed"), std::string("interrupted: the run was killed")));
}

// `script` gives the runner a terminal, as a user's shell does.
CommandResult on_a_terminal(const std::string& vesica_args, const fs::path& dir) {
  const std::string command = quoted((bin_dir() / "vesica").string()) + " " + vesica_args;
  return run_command("script -qec " + quoted(command) + " /dev/null", dir);
}

TEST(RunnerProcess, TheRunningStagesOwnProgressShowsOnATerminalAndJsonStaysQuiet) {
  const fs::path dir = scratch_dir("runner-progress");
  const fs::path file = two_stages(dir, "label: B, progress_steps: 5");
  const CommandResult shown = on_a_terminal("run " + quoted(file.string()), dir);
  EXPECT_EQ(shown.exit_code, 0) << shown.out;
  // Redrawn in place under the runner's lines, with the stage's id in front.
  EXPECT_TRUE(std::regex_search(shown.out, std::regex("\r\033\\[K  \\[b\\] step [1-4]/5 +[0-9]+%")))
      << shown.out;
  EXPECT_NE(shown.out.find("  [b] [teststage] step 5/5 100%"), std::string::npos) << shown.out;

  const CommandResult quiet =
      on_a_terminal("run " + quoted(file.string()) + " --json --force", dir);
  EXPECT_EQ(quiet.exit_code, 0) << quiet.out;
  const auto j = nlohmann::json::parse(quiet.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << quiet.out;  // nothing but the JSON on the terminal
  EXPECT_EQ(j["ran"], (Ids{"a", "b"}));
}

// A run whose stderr is a pipe (a CI log, `2>&1 | tee`) still shows what each stage is
// doing: one whole line per step, no terminal redrawing.
TEST(RunnerProcess, APipedRunLogsALinePerStepOfTheRunningStage) {
  const fs::path dir = scratch_dir("runner-progress-piped");
  const fs::path file = two_stages(dir, "label: B, progress_steps: 3");
  const CommandResult piped = run_vesica("run " + quoted(file.string()), dir);
  EXPECT_EQ(piped.exit_code, 0) << piped.out;
  for (const char* step : {"  [b] step 1/3  33%", "  [b] step 2/3  67%", "step 3/3 100%"})
    EXPECT_NE(piped.err.find(step), std::string::npos) << piped.err;
  EXPECT_EQ(piped.err.find('\r'), std::string::npos) << piped.err;
  EXPECT_EQ(piped.err.find("\033["), std::string::npos) << piped.err;
}

TEST(RunnerProcess, StatusExitsOneWhenSomethingWouldRunAndNamesTheFailure) {
  const fs::path dir = scratch_dir("runner-status-exit");
  const fs::path file = two_stages(dir, "label: B, fail: true");
  const std::string status = "status " + quoted(file.string());
  EXPECT_EQ(run_vesica(status, dir).exit_code, 1);  // nothing ran yet
  EXPECT_EQ(run_vesica("run " + quoted(file.string()), dir).exit_code, 1);
  const CommandResult failed = run_vesica(status, dir);
  EXPECT_EQ(failed.exit_code, 1);
  EXPECT_NE(failed.out.find("b      failed (exit 1): vesica-teststage: error: b.txt: told to fail "
                            "(remove --fail)"),
            std::string::npos)
      << failed.out;
  two_stages(dir, "label: B");
  ASSERT_EQ(run_vesica("run " + quoted(file.string()), dir).exit_code, 0);
  EXPECT_EQ(run_vesica(status, dir).exit_code, 0);
  write_text(dir / "out/b.txt", "mine\n");  // an edit kept is nothing to run
  const CommandResult kept = run_vesica(status, dir);
  EXPECT_EQ(kept.exit_code, 0);
  EXPECT_NE(kept.out.find("b      edited (kept): b.txt"), std::string::npos) << kept.out;
  EXPECT_NE(kept.out.find("kept your edits: b.txt (b)"), std::string::npos) << kept.out;
}

TEST(RunnerProcess, AFileSavedByHandAfterItsStageFailedIsKept) {
  const fs::path dir = scratch_dir("runner-edit-after-failure");
  write_text(dir / "p.yaml",
             "workdir: out\n"
             "stages:\n"
             "  a: {tool: teststage, output: a.txt, params: {label: A, fail: true}}\n"
             "  b: {tool: teststage, input: a.txt, output: b.txt, params: {label: B}}\n");
  int code = 0;
  EXPECT_EQ(run_json(dir / "p.yaml", dir, "", &code), Ids{});
  EXPECT_EQ(code, 1);
  write_text(dir / "out/a.txt", "made by hand\n");  // what a user does when a stage fails
  EXPECT_EQ(status_of(dir / "p.yaml", dir).at("a").first, "edited");
  EXPECT_EQ(run_json(dir / "p.yaml", dir), Ids{"b"});
  EXPECT_EQ(slurp(dir / "out/b.txt"), "made by hand\nB\n");
  EXPECT_EQ(run_json(dir / "p.yaml", dir), Ids{});
}

TEST(RunnerProcess, AMistypedRunOptionIsAnsweredWithTheCloseMatch) {
  const fs::path dir = scratch_dir("runner-did-you-mean");
  const fs::path file = two_stages(dir, "label: B");
  const CommandResult r = run_vesica("run --wokdir elsewhere " + quoted(file.string()), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown option --wokdir (did you mean --workdir?)"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

// A pipeline installed with vesica (<prefix>/share/vesica/pipelines beside <prefix>/bin)
// writes under the folder it is run from, not into the installation.
TEST(RunnerProcess, AnInstalledPipelineWritesUnderTheCurrentFolder) {
  const fs::path dir = scratch_dir("runner-installed-workdir");
  const fs::path prefix = dir / "prefix", here = dir / "here";
  fs::create_directories(prefix / "bin");
  fs::create_directories(here);
  for (const char* exe : {"vesica", "vesica-teststage"})
    fs::copy_file(bin_dir() / exe, prefix / "bin" / exe);
  const fs::path installed = prefix / "share/vesica/pipelines";
  fs::create_directories(installed);
  const fs::path file = two_stages(installed, "label: B");
  const CommandResult r =
      run_command("cd " + quoted(here.string()) + " && " +
                      quoted((prefix / "bin/vesica").string()) + " run " + quoted(file.string()),
                  dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(here / "p" / "b.txt")) << r.err;  // ./<pipeline name>
  EXPECT_FALSE(fs::exists(installed / "out"));
}
