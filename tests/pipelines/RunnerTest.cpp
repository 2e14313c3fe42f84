// `vesica run` and `vesica status` on a chain of test stages a -> b -> c -> d, where the
// expected file contents follow by hand from the stage rule "inputs, then the label".
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <regex>

#include "PipelineTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

// c writes a folder; d reads a file inside it, so d depends on c by path.
std::string chain_yaml(const std::string& c_params = "{label: C, dir: true}") {
  return "pipeline: chain\n"
         "workdir: out\n"
         "stages:\n"
         "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
         "  b: {tool: teststage, input: a.txt, output: b.txt, params: {label: B}}\n"
         "  c: {tool: teststage, input: b.txt, output: c/dir, params: " +
         c_params +
         "}\n"
         "  d: {tool: teststage, input: c/dir/data.txt, output: d.txt, params: {label: D}}\n";
}

struct Chain {
  fs::path dir, file, out;
  explicit Chain(const std::string& name) : dir(scratch_dir(name)) {
    file = dir / "chain.yaml";
    out = dir / "out";
    write_text(file, chain_yaml());
  }
};

// The chain run once, then b.txt saved by hand.
Chain edited_chain(const std::string& name, const std::string& text = "mine\n") {
  Chain c(name);
  EXPECT_EQ(run_json(c.file, c.dir).size(), 4u);
  write_text(c.out / "b.txt", text);
  return c;
}

}  // namespace

TEST(Runner, FirstRunRunsEverythingSecondRunNothing) {
  Chain c("runner-noop");
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"a", "b", "c", "d"}));
  EXPECT_EQ(slurp(c.out / "d.txt"), "A\nB\nC\nD\n");
  EXPECT_EQ(slurp(c.out / "c/dir/data.txt"), "A\nB\nC\n");
  // Manifests and reports live in .vesica/, named by the stage, not beside the outputs.
  EXPECT_TRUE(fs::exists(c.out / ".vesica/c.manifest.json"));
  EXPECT_TRUE(fs::exists(c.out / ".vesica/c.json"));
  std::vector<std::string> visible;
  for (const auto& e : fs::directory_iterator(c.out)) visible.push_back(e.path().filename());
  std::sort(visible.begin(), visible.end());
  EXPECT_EQ(visible, (Ids{".vesica", "a.txt", "b.txt", "c", "d.txt"}));
  EXPECT_EQ(run_json(c.file, c.dir), Ids{});
  for (const auto& [stage, st] : status_of(c.file, c.dir)) EXPECT_EQ(st.first, "fresh") << stage;
}

TEST(Runner, AnEditedIntermediateIsKeptAndEverythingAfterItReruns) {
  const Chain c = edited_chain("runner-edit", "edited by hand\n");
  auto st = status_of(c.file, c.dir);
  EXPECT_EQ(st["a"].first, "fresh");
  EXPECT_EQ(st["b"], std::make_pair(std::string("edited"), std::string("b.txt")));
  EXPECT_EQ(st["c"],
            std::make_pair(std::string("stale"), std::string("input b.txt changed (upstream b)")));
  EXPECT_EQ(st["d"], std::make_pair(std::string("stale"), std::string("upstream c is stale")));

  const CommandResult r = run_vesica("run " + quoted(c.file.string()), c.dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("vesica: kept your edits: b.txt (b);"), std::string::npos) << r.err;
  EXPECT_EQ(slurp(c.out / "b.txt"), "edited by hand\n");  // byte for byte what was saved
  // c appends its label to what b left, d to what c left.
  EXPECT_EQ(slurp(c.out / "d.txt"), "edited by hand\nC\nD\n");
  EXPECT_EQ(run_json(c.file, c.dir), Ids{});
  EXPECT_EQ(status_of(c.file, c.dir)["b"].first, "edited");
  EXPECT_FALSE(fs::exists(c.out / ".vesica/backup"));  // nothing was replaced
}

TEST(Runner, ForceAndFromRerunAroundAnEditButNeverOverIt) {
  const Chain c = edited_chain("runner-edit-force");
  EXPECT_EQ(run_json(c.file, c.dir, "--force"), (Ids{"a", "c", "d"}));
  EXPECT_EQ(run_json(c.file, c.dir, "--from b"), (Ids{"c", "d"}));
  EXPECT_EQ(slurp(c.out / "b.txt"), "mine\n");
}

TEST(Runner, AnEditWinsOverAChangedParameterUntilReset) {
  const Chain c = edited_chain("runner-edit-param");
  const std::string changed =
      std::regex_replace(chain_yaml(), std::regex("label: B\\}"), "label: B2}");
  ASSERT_NE(changed, chain_yaml());
  write_text(c.file, changed);
  const auto st = status_of(c.file, c.dir);
  EXPECT_EQ(st.at("b").first, "edited");
  EXPECT_NE(st.at("b").second.find("also parameter label changed (B -> B2)"), std::string::npos)
      << st.at("b").second;
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"c", "d"}));
  EXPECT_EQ(slurp(c.out / "d.txt"), "mine\nC\nD\n");
  EXPECT_EQ(run_json(c.file, c.dir, "--discard-edits b"), (Ids{"b", "c", "d"}));
  EXPECT_EQ(slurp(c.out / "d.txt"), "A\nB2\nC\nD\n");
}

// The one backup folder of a stage (.vesica/backup/<stage>/<UTC time>/).
fs::path only_backup(const fs::path& out, const std::string& stage) {
  std::vector<fs::path> folders;
  for (const auto& e : fs::directory_iterator(out / ".vesica/backup" / stage))
    folders.push_back(e.path());
  return folders.size() == 1 ? folders[0] : fs::path();
}

TEST(Runner, ResetRegeneratesAnEditAndTheBackupHoldsIt) {
  const Chain c = edited_chain("runner-reset");
  ASSERT_EQ(run_json(c.file, c.dir), (Ids{"c", "d"}));
  const CommandResult r = run_vesica("reset " + quoted(c.file.string()) + " b", c.dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(slurp(c.out / "b.txt"), "A\nB\n");
  EXPECT_EQ(slurp(c.out / "d.txt"), "A\nB\nC\nD\n");
  const fs::path backup = only_backup(c.out, "b");
  ASSERT_FALSE(backup.empty());
  EXPECT_TRUE(std::regex_match(backup.filename().string(), std::regex("\\d{8}T\\d{6}Z"))) << backup;
  EXPECT_EQ(slurp(backup / "b.txt"), "mine\n");
  EXPECT_NE(r.err.find("b: saved b.txt to " + backup.string()), std::string::npos) << r.err;
  for (const auto& [stage, st] : status_of(c.file, c.dir)) EXPECT_EQ(st.first, "fresh") << stage;
}

TEST(Runner, AcceptMakesAnEditTheStagesOwnAndALaterRerunStillSavesIt) {
  const Chain c = edited_chain("runner-accept");
  const CommandResult r = run_vesica("accept " + quoted(c.file.string()) + " b", c.dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("b: b.txt accepted as its output"), std::string::npos) << r.err;
  auto st = status_of(c.file, c.dir);
  EXPECT_EQ(st.at("b").first, "fresh");
  EXPECT_EQ(st.at("c").second, "input b.txt changed (upstream b)");
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"c", "d"}));
  EXPECT_EQ(slurp(c.out / "d.txt"), "mine\nC\nD\n");
  // Accepting again finds nothing to accept; rerunning b replaces the accepted file, which
  // is still someone's work, so it is saved first.
  EXPECT_NE(
      run_vesica("accept " + quoted(c.file.string()) + " b", c.dir).err.find("nothing to accept"),
      std::string::npos);
  EXPECT_EQ(run_json(c.file, c.dir, "--from b"), (Ids{"b", "c", "d"}));
  EXPECT_EQ(slurp(c.out / "b.txt"), "A\nB\n");
  EXPECT_EQ(slurp(only_backup(c.out, "b") / "b.txt"), "mine\n");
}

TEST(Runner, ParameterChangeRerunsThatStageAndBelow) {
  Chain c("runner-param");
  ASSERT_EQ(run_json(c.file, c.dir).size(), 4u);
  write_text(c.file, chain_yaml("{label: C2, dir: true}"));
  auto st = status_of(c.file, c.dir);
  EXPECT_EQ(st["b"].first, "fresh");
  EXPECT_EQ(st["c"].second, "parameter label changed (C -> C2)");
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"c", "d"}));
  EXPECT_EQ(slurp(c.out / "d.txt"), "A\nB\nC2\nD\n");
}

TEST(Runner, SameSizeEditInsideAFolderOutputIsNoticedAndKept) {
  Chain c("runner-folder-edit");
  ASSERT_EQ(run_json(c.file, c.dir).size(), 4u);
  write_text(c.out / "c/dir/data.txt", "X\nY\nZ\n");  // as long as "A\nB\nC\n"
  EXPECT_EQ(status_of(c.file, c.dir)["c"],
            std::make_pair(std::string("edited"), std::string("c/dir")));
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"d"}));
  EXPECT_EQ(slurp(c.out / "c/dir/data.txt"), "X\nY\nZ\n");
  EXPECT_EQ(slurp(c.out / "d.txt"), "X\nY\nZ\nD\n");
}

TEST(Runner, TouchedButUnchangedFileIsFresh) {
  Chain c("runner-touch");
  ASSERT_EQ(run_json(c.file, c.dir).size(), 4u);
  write_text(c.out / "b.txt", slurp(c.out / "b.txt"));  // same bytes, new mtime
  EXPECT_EQ(run_json(c.file, c.dir), Ids{});
}

TEST(Runner, FailingStageKeepsEarlierOutputsAndNextRunResumesThere) {
  Chain c("runner-fail");
  write_text(c.file, chain_yaml("{label: C, dir: true, fail: true}"));
  const CommandResult r = run_vesica("run " + quoted(c.file.string()), c.dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("stage 'c' failed (exit 1): vesica-teststage: error: c/dir: told to fail"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(slurp(c.out / "a.txt"), "A\n");
  EXPECT_EQ(slurp(c.out / "b.txt"), "A\nB\n");
  EXPECT_FALSE(fs::exists(c.out / "c/dir"));
  EXPECT_FALSE(fs::exists(c.out / "d.txt"));

  write_text(c.file, chain_yaml());
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"c", "d"}));
  EXPECT_EQ(slurp(c.out / "d.txt"), "A\nB\nC\nD\n");
}

TEST(Runner, FailureOfARerunKeepsTheOldOutputAndStaysStale) {
  Chain c("runner-fail-rerun");
  ASSERT_EQ(run_json(c.file, c.dir).size(), 4u);
  write_text(c.file, chain_yaml("{label: C, dir: true, fail: true}"));
  int code = 0;
  EXPECT_EQ(run_json(c.file, c.dir, "", &code), Ids{});
  EXPECT_EQ(code, 1);
  EXPECT_EQ(slurp(c.out / "c/dir/data.txt"), "A\nB\nC\n");  // written atomically before
  write_text(c.file, chain_yaml());
  // The manifest was removed when c started, so c reruns even with its old parameters.
  EXPECT_EQ(status_of(c.file, c.dir)["c"],
            std::make_pair(std::string("failed"),
                           std::string("failed (exit 1): vesica-teststage: error: c/dir: told to "
                                       "fail (remove --fail)")));
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"c", "d"}));
}

TEST(Runner, OnlyFromAndForceSelectStages) {
  Chain c("runner-select");
  ASSERT_EQ(run_json(c.file, c.dir).size(), 4u);
  EXPECT_EQ(run_json(c.file, c.dir, "--from b"), (Ids{"b", "c", "d"}));
  EXPECT_EQ(run_json(c.file, c.dir, "--only c --force"), Ids{"c"});
  EXPECT_EQ(run_json(c.file, c.dir, "--only c"), Ids{});
  const CommandResult r = run_vesica("run " + quoted(c.file.string()) + " --only cc", c.dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no stage named 'cc' (did you mean 'c'?)"), std::string::npos) << r.err;
}

TEST(Runner, WorkdirOverride) {
  Chain c("runner-workdir");
  EXPECT_EQ(run_json(c.file, c.dir, "--workdir " + quoted((c.dir / "elsewhere").string())).size(),
            4u);
  EXPECT_EQ(slurp(c.dir / "elsewhere" / "d.txt"), "A\nB\nC\nD\n");
  EXPECT_FALSE(fs::exists(c.out));
}

TEST(Runner, IndependentStagesRunInParallel) {
  const fs::path dir = scratch_dir("runner-parallel");
  const fs::path file = dir / "diamond.yaml";
  // b and c each sleep 1 s; one after the other they would take at least 2 s.
  write_text(
      file,
      "stages:\n"
      "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
      "  b: {tool: teststage, input: a.txt, output: b.txt, params: {label: B, sleep_ms: 1000}}\n"
      "  c: {tool: teststage, input: a.txt, output: c.txt, params: {label: C, sleep_ms: 1000}}\n"
      "  d:\n"
      "    tool: teststage\n"
      "    input: b.txt\n"
      "    inputs: {aux: c.txt}\n"
      "    output: d.txt\n"
      "    params: {label: D}\n");
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(run_json(file, dir, "-j 2").size(), 4u);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(slurp(dir / "d.txt"), "A\nB\nA\nC\nD\n");
  EXPECT_LT(seconds, 1.9) << "b and c did not overlap";
}

TEST(Runner, InterruptedRunResumesAtTheInterruptedStage) {
  Chain c("runner-interrupt");
  write_text(c.file, chain_yaml("{label: C, dir: true, sleep_ms: 4000}"));
  // timeout signals the whole process group: the runner and the sleeping stage c.
  const CommandResult r =
      run_command("timeout -s INT 2 " + quoted((bin_dir() / "vesica").string()) + " run " +
                      quoted(c.file.string()),
                  c.dir);
  EXPECT_EQ(r.exit_code, 124) << r.err;  // timeout's code for "had to stop it"
  EXPECT_NE(r.err.find("vesica: interrupted by SIGINT: c stopped and will run again"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(slurp(c.out / "b.txt"), "A\nB\n");
  EXPECT_FALSE(fs::exists(c.out / "c/dir"));
  auto st = status_of(c.file, c.dir);
  EXPECT_EQ(st["b"].first, "fresh");
  EXPECT_EQ(st["c"], std::make_pair(std::string("failed"), std::string("interrupted: SIGINT")));
  write_text(c.file, chain_yaml());
  EXPECT_EQ(run_json(c.file, c.dir), (Ids{"c", "d"}));
  EXPECT_EQ(slurp(c.out / "d.txt"), "A\nB\nC\nD\n");
}

TEST(Runner, NewToolVersionAndEditedExternalInputMakeStagesStale) {
  const fs::path dir = scratch_dir("runner-version");
  write_text(dir / "data" / "measured.csv", "1,2\n");
  const fs::path file = dir / "p.yaml";
  write_text(
      file,
      "workdir: out\n"
      "inputs: {cmg: data/measured.csv}\n"
      "stages:\n"
      "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
      "  b: {tool: teststage, input: a.txt, inputs: {aux: '${inputs.cmg}'}, output: b.txt}\n");
  ASSERT_EQ(run_json(file, dir).size(), 2u);
  EXPECT_EQ(slurp(dir / "out/b.txt"), "A\n1,2\nstage\n");

  auto manifest = nlohmann::json::parse(slurp(dir / "out/.vesica/a.manifest.json"));
  manifest["version"] = "0.0.1";
  write_text(dir / "out/.vesica/a.manifest.json", manifest.dump());
  write_text(dir / "data" / "measured.csv", "1,3\n");
  auto st = status_of(file, dir);
  EXPECT_EQ(st["a"].second, std::string("tool version changed (0.0.1 -> ") + VESICA_VERSION + ")");
  EXPECT_EQ(st["b"].second, "input ../data/measured.csv changed");
  EXPECT_EQ(run_json(file, dir), (Ids{"a", "b"}));
  EXPECT_EQ(slurp(dir / "out/b.txt"), "A\n1,3\nstage\n");
}
