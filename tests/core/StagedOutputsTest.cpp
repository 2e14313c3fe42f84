// A stage's outputs are replaced together, and only when the stage succeeded.
#include "vesica/core/StagedOutputs.h"

#include <fstream>
#include <sstream>

#include "TestData.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/ContentHash.h"
#include "vesica/core/Error.h"
#include "vesica/core/StageRecord.h"

namespace fs = std::filesystem;
using vesica::test::file_text;

namespace {

int entries(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) (void)e, ++n;
  return n;
}

}  // namespace

TEST(StagedOutputs, AStageFailingAtItsLastOutputLeavesEveryEarlierOutputAsItWas) {
  const fs::path dir = vesica::test::scratch_dir("staged-fail");
  vesica::write_text_atomically(dir / "bladder.msh", "old mesh");
  vesica::write_text_atomically(dir / "bladder.vtu", "old vtu");
  vesica::begin_staging();
  vesica::write_text_atomically(dir / "bladder.msh", "new mesh");
  EXPECT_EQ(file_text(dir / "bladder.msh"), "old mesh");  // not yet replaced
  vesica::discard_staged_outputs();                       // the .vtu failed
  EXPECT_EQ(file_text(dir / "bladder.msh"), "old mesh");
  EXPECT_EQ(file_text(dir / "bladder.vtu"), "old vtu");
  EXPECT_EQ(entries(dir), 2);  // no temporary left
}

// A full disk at the commit's second rename (tests/support/FailRename.c, linked into this
// binary): the first output, already renamed into place, goes back to its earlier content,
// and a new output that had no earlier file is not left behind alone.
TEST(StagedOutputs, ARenameRefusedDuringTheCommitPutsBackTheOutputsAlreadyReplaced) {
  const fs::path dir = vesica::test::scratch_dir("staged-commit-fails");
  vesica::write_text_atomically(dir / "bladder.stl", "old surface");
  vesica::write_text_atomically(dir / "bladder.stl.regions.json", "old regions");
  vesica::begin_staging();
  vesica::write_text_atomically(dir / "new.txt", "made by this run");
  vesica::write_text_atomically(dir / "bladder.stl", "new surface");
  vesica::write_text_atomically(dir / "bladder.stl.regions.json", "new regions");
  ::setenv("VESICA_TEST_FAIL_RENAME", "regions.json", 1);
  EXPECT_THROW(vesica::commit_staged_outputs(), vesica::Error);
  ::unsetenv("VESICA_TEST_FAIL_RENAME");
  EXPECT_EQ(file_text(dir / "bladder.stl"), "old surface");
  EXPECT_EQ(file_text(dir / "bladder.stl.regions.json"), "old regions");
  EXPECT_FALSE(fs::exists(dir / "new.txt"));
  EXPECT_EQ(entries(dir), 2);  // no temporary, no second name left
}

TEST(StagedOutputs, ASuccessfulStageReplacesAllItsOutputsAndItsManifestNamesTheirContent) {
  const fs::path dir = vesica::test::scratch_dir("staged-commit");
  vesica::write_text_atomically(dir / "bladder.msh", "old mesh");
  const char* argv[] = {"vesica-x"};
  vesica::StageRecord record("x", 1, argv);
  vesica::begin_staging();
  vesica::write_text_atomically(dir / "bladder.msh", "new mesh");
  vesica::write_atomically(dir / "sim", [](const fs::path& tmp) {
    fs::create_directories(tmp);
    std::ofstream(tmp / "history.csv") << "time_s\n0\n";
  });
  record.add_output(dir / "bladder.msh");
  record.add_output(dir / "sim" / "history.csv");
  record.write(dir / "summary.json", dir / "manifest.json");
  EXPECT_FALSE(fs::exists(dir / "manifest.json"));
  vesica::commit_staged_outputs();
  EXPECT_EQ(file_text(dir / "bladder.msh"), "new mesh");
  EXPECT_EQ(file_text(dir / "sim" / "history.csv"), "time_s\n0\n");
  std::ifstream m(dir / "manifest.json");
  const auto manifest = nlohmann::json::parse(m);
  EXPECT_EQ(manifest["outputs"][0]["hash"], vesica::content_hash(dir / "bladder.msh"));
  EXPECT_EQ(manifest["outputs"][1]["hash"], vesica::content_hash(dir / "sim" / "history.csv"));
  EXPECT_EQ(manifest["outputs"][0]["path"], (dir / "bladder.msh").string());
}
