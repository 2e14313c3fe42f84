// vesica never loses a user's file: every failure leaves the earlier outputs as they were
// (their hashes unchanged), exits non-zero with one line naming the file, writes no
// manifest and leaves no temporary behind; and no output ever replaces a folder vesica
// did not write, the current folder or an input.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <sstream>
#include <thread>

#include "ShellCommand.h"
#include "TestData.h"
#include "vesica/core/ContentHash.h"

namespace fs = std::filesystem;
using vesica::test::run_command;

namespace {

std::string tool(const std::string& name) {
  return (vesica::test::bin_dir() / name).string();
}

// Every file under `dir` (recursively) with its hash.
std::map<std::string, std::string> hashes(const fs::path& dir) {
  std::map<std::string, std::string> h;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file())
      h[fs::relative(e.path(), dir).string()] = vesica::content_hash(e.path());
  return h;
}

// The environment that makes the rename of an output named like `name` fail as on a full
// disk (tests/support/FailRename.c preloaded into the stage executable).
std::string fail_rename(const std::string& name) {
  return "LD_PRELOAD='" VESICA_FAIL_RENAME_LIBRARY "' VESICA_TEST_FAIL_RENAME=" + name + " ";
}

int temporaries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    n += e.path().filename().string().rfind(".tmp-", 0) == 0;
  return n;
}

// The command in `dir` under a file-size limit of `kib` KiB (the tools ignore SIGXFSZ).
vesica::test::CommandResult run_limited(const fs::path& dir, int kib, const std::string& command) {
  return run_command("cd '" + dir.string() + "' && bash -c 'ulimit -f " + std::to_string(kib) +
                     "; exec " + command + "'");
}

bool one_line_naming(const std::string& output, const std::string& file) {
  const std::string line = output.substr(output.rfind('\n', output.size() - 2) + 1);
  return line.find("error: ") != std::string::npos && line.find(file) != std::string::npos &&
         line.size() <= 301;
}

// A complete run of every stage on a small phantom, made once and copied per test.
class DataSafety : public ::testing::Test {
 protected:
  // Where SetUpTestSuite made the run (the build tree's scratch folder, as every test's).
  static fs::path& reference() {
    static fs::path made;
    return made;
  }

  static void SetUpTestSuite() {
    const fs::path d = vesica::test::scratch_dir("safety-ref");
    reference() = d;
    const std::string in = "cd '" + d.string() + "' && ";
    const std::string steps[] = {
        tool("vesica-phantom") + " -o ct --bladder-ml 150 --spacing-mm 4",
        tool("vesica-segment") + " ct -o bladder.nii.gz --report segment.json",
        tool("vesica-surface") + " bladder.nii.gz -o bladder.vtp --edge-mm 8 --report surface.json",
        tool("vesica-mesh") + " bladder.vtp -o bladder.msh --report mesh.json",
        tool("vesica-simulate") + " bladder.vtu -o sim --capacity-ml 100 --no-void",
        tool("vesica-compare") + " --simulated sim/history.csv -o report --report compare.json"};
    for (const std::string& step : steps) {
      const auto r = run_command(in + step);
      ASSERT_EQ(r.exit_code, 0) << step << "\n" << r.output;
    }
  }

  void SetUp() override {
    dir_ =
        vesica::test::scratch_dir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::copy(reference(), dir_, fs::copy_options::recursive);
    before_ = hashes(dir_);
  }

  // The failure promise: exit 1, one line naming `file`, nothing changed, no temporary.
  void expect_nothing_lost(const vesica::test::CommandResult& r, const std::string& file) {
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_TRUE(one_line_naming(r.output, file)) << r.output;
    EXPECT_EQ(hashes(dir_), before_);
    EXPECT_EQ(temporaries(dir_), 0);
  }

  fs::path dir_;
  std::map<std::string, std::string> before_;
};

TEST_F(DataSafety, AFullDiskLeavesEveryStagesEarlierOutputsAsTheyWere) {
  expect_nothing_lost(
      run_limited(dir_, 1, tool("vesica-segment") + " ct -o bladder.nii.gz --report segment.json"),
      "bladder.nii.gz");
  expect_nothing_lost(
      run_limited(dir_, 2,
                  tool("vesica-surface") + " bladder.nii.gz -o bladder.vtp --edge-mm 8 --report "
                                           "surface.json"),
      "bladder.vtp");
  expect_nothing_lost(
      run_limited(dir_, 40, tool("vesica-mesh") + " bladder.vtp -o bladder.msh --report mesh.json"),
      "bladder.msh");
  expect_nothing_lost(
      run_limited(dir_, 12,
                  tool("vesica-simulate") + " bladder.vtu -o sim --capacity-ml 100 --no-void"),
      "sim");
  expect_nothing_lost(
      run_limited(dir_, 4,
                  tool("vesica-compare") + " --simulated sim/history.csv -o report --report "
                                           "compare.json"),
      "report");
}

TEST_F(DataSafety, AReportThatCannotBeWrittenKeepsTheEarlierPageAndMetricsTogether) {
  // The page fails after the metrics were written: neither may change.
  const auto r = run_command("cd '" + dir_.string() + "' && " + fail_rename("index.html") +
                             tool("vesica-compare") +
                             " --simulated sim/history.csv -o report --report compare.json");
  expect_nothing_lost(r, "index.html");
}

TEST_F(DataSafety, ASurfaceWhoseSidecarCannotBeWrittenKeepsTheEarlierPair) {
  auto r = run_command("cd '" + dir_.string() + "' && " + tool("vesica-surface") +
                       " bladder.nii.gz -o bladder.stl --edge-mm 8");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  before_ = hashes(dir_);
  r = run_command("cd '" + dir_.string() + "' && " + fail_rename("regions.json") +
                  tool("vesica-surface") + " bladder.nii.gz -o bladder.stl --edge-mm 6");
  expect_nothing_lost(r, "bladder.stl.regions.json");
}

TEST_F(DataSafety, AKilledSimulationLeavesTheEarlierResultsAndNoHalfWrittenFolder) {
  const std::string command =
      "cd '" + dir_.string() + "' && exec " + tool("vesica-simulate") +
      " bladder.vtu -o sim --capacity-ml 300 --hold-s 3600 --straining-kpa 4";
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the simulation ended before it was killed";
  EXPECT_EQ(hashes(dir_ / "sim"), hashes(reference() / "sim"));
  // The next run removes the killed run's temporary folder.
  const auto r = run_command("cd '" + dir_.string() + "' && " + tool("vesica-simulate") +
                             " bladder.vtu -o sim --capacity-ml 100 --no-void");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(temporaries(dir_), 0);
}

TEST_F(DataSafety, PhantomIntoTheParentFolderIsRefusedAndDeletesNothing) {
  fs::create_directories(dir_ / "work");
  const auto r = run_command("cd '" + (dir_ / "work").string() + "' && " + tool("vesica-phantom") +
                             " -o .. --spacing-mm 4");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("current folder"), std::string::npos) << r.output;
  EXPECT_EQ(hashes(dir_), before_);
  const auto v = run_command("cd '" + (dir_ / "work").string() + "' && " + tool("vesica") +
                             " phantom .. --spacing-mm 4");
  EXPECT_NE(v.exit_code, 0) << v.output;
  EXPECT_EQ(hashes(dir_), before_);
}

TEST_F(DataSafety, APipelineWhoseOutputIsItsOwnFolderDeletesNothing) {
  std::ofstream(dir_ / "p.yaml") << "stages:\n"
                                    "  phantom: {output: ., params: {spacing_mm: 4}}\n";
  before_ = hashes(dir_);
  const auto r = run_command(tool("vesica") + " run '" + (dir_ / "p.yaml").string() +
                             "' --workdir '" + dir_.string() + "'");
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_EQ(hashes(dir_), before_);
  // validate says why, at the output's line.
  const auto v = run_command(tool("vesica") + " validate '" + (dir_ / "p.yaml").string() + "'");
  EXPECT_EQ(v.exit_code, 2) << v.output;
  EXPECT_NE(v.output.find("p.yaml:2:"), std::string::npos) << v.output;
  EXPECT_NE(v.output.find("output '.' of stage 'phantom' is the workdir"), std::string::npos)
      << v.output;
}

TEST_F(DataSafety, AFolderTheUserMadeIsNotReplacedByAnOutput) {
  fs::create_directories(dir_ / "mine");
  std::ofstream(dir_ / "mine" / "notes.txt") << "mine";
  before_ = hashes(dir_);
  const auto r = run_command("cd '" + dir_.string() + "' && " + tool("vesica-simulate") +
                             " bladder.vtu -o mine --capacity-ml 100 --no-void");
  expect_nothing_lost(r, "mine");
}

TEST_F(DataSafety, AnOutputMayNotReplaceItsInput) {
  const auto r = run_command("cd '" + dir_.string() + "' && " + tool("vesica-surface") +
                             " bladder.vtp -o bladder.vtp");
  expect_nothing_lost(r, "bladder.vtp");
}

}  // namespace

namespace {

TEST_F(DataSafety, SettingsNoBladderTakesOrThatBoundNoWorkAreRefusedByName) {
  const std::pair<const char*, const char*> cases[] = {
      {"--hold-s 1e30", "--hold-s"},  // frames until the disk is full
      {"--k-kpa 0", "--k-kpa"},       // was silently the default
      {"--mu-kpa 1e30", "--mu-kpa"},  // Newton spun for ever
      {"--mu-kpa nan", "--mu-kpa"},   // NaN passes a plain range check
      {"--detrusor-kpa -3", "--detrusor-kpa"},
      {"--p-open-cmh2o -1", "--p-open-cmh2o"},
      {"--support-kpa-per-mm -1", "--support-kpa-per-mm"}};
  for (const auto& [arguments, option] : cases) {
    const auto r = run_command("cd '" + dir_.string() + "' && " + tool("vesica-simulate") +
                               " bladder.vtu -o sim2 " + arguments);
    EXPECT_EQ(r.exit_code, 2) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(option), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir_ / "sim2")) << arguments;
  }
}

}  // namespace
