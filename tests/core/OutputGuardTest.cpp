// vesica deletes only what it made: the paths an output may and may not replace.
#include "vesica/core/OutputGuard.h"

#include <unistd.h>

#include <fstream>
#include <sstream>

#include "TestData.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"

namespace fs = std::filesystem;
using vesica::test::file_text;

namespace {

void write_folder(const fs::path& target, const std::string& name, const std::string& text) {
  vesica::write_atomically(target, [&](const fs::path& tmp) {
    fs::create_directories(tmp);
    std::ofstream(tmp / name) << text;
  });
}

// Runs `body` with the current folder set to `dir`, then restores it.
template <class Body>
void inside(const fs::path& dir, const Body& body) {
  const fs::path before = fs::current_path();
  fs::current_path(dir);
  try {
    body();
  } catch (...) {
    fs::current_path(before);
    throw;
  }
  fs::current_path(before);
}

}  // namespace

TEST(OutputGuard, AFolderTheUserMadeIsNeverReplaced) {
  const fs::path dir = vesica::test::scratch_dir("guard-user-folder");
  fs::create_directories(dir / "ct");
  std::ofstream(dir / "ct" / "notes.txt") << "the user's";
  EXPECT_THROW(write_folder(dir / "ct", "slice.dcm", "x"), vesica::Error);
  EXPECT_EQ(file_text(dir / "ct" / "notes.txt"), "the user's");
  EXPECT_FALSE(fs::exists(dir / "ct" / "slice.dcm"));
}

TEST(OutputGuard, AnEmptyFolderOrOneVesicaWroteIsReplacedWhole) {
  const fs::path dir = vesica::test::scratch_dir("guard-own-folder");
  fs::create_directories(dir / "sim");  // empty: nothing to lose
  vesica::write_atomically(dir / "sim", [&](const fs::path& tmp) {
    fs::create_directories(tmp / "series");
    for (int step = 0; step < 39; ++step)
      std::ofstream(tmp / "series" / ("step_" + std::to_string(step) + ".vtu")) << step;
  });
  EXPECT_TRUE(vesica::carries_folder_marker(dir / "sim"));
  write_folder(dir / "sim", "history.csv", "second run");
  // The second run's folder, not a mixture: no step file of the first run is left.
  EXPECT_EQ(file_text(dir / "sim" / "history.csv"), "second run");
  EXPECT_FALSE(fs::exists(dir / "sim" / "series"));
}

TEST(OutputGuard, TheCurrentFolderAndItsParentsAreRefused) {
  const fs::path dir = vesica::test::scratch_dir("guard-parent");
  fs::create_directories(dir / "work");
  std::ofstream(dir / "work" / "pipeline.yaml") << "stages: {}";
  std::ofstream(dir / "keep.txt") << "parent's file";
  inside(dir / "work", [&] {
    EXPECT_THROW(write_folder("..", "slice.dcm", "x"), vesica::Error);
    EXPECT_THROW(write_folder(".", "slice.dcm", "x"), vesica::Error);
    EXPECT_THROW(write_folder("sub/../../work", "slice.dcm", "x"), vesica::Error);
  });
  EXPECT_EQ(file_text(dir / "keep.txt"), "parent's file");
  EXPECT_EQ(file_text(dir / "work" / "pipeline.yaml"), "stages: {}");
  try {
    inside(dir / "work", [&] { write_folder("..", "slice.dcm", "x"); });
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find("current folder"), std::string::npos) << e.what();
  }
}

TEST(OutputGuard, AnInputAndTheFolderHoldingItAreNeverReplaced) {
  const fs::path dir = vesica::test::scratch_dir("guard-input");
  write_folder(dir / "made", "mesh.msh", "the input");
  vesica::protect_input(dir / "made" / "mesh.msh");
  EXPECT_THROW(vesica::write_text_atomically(dir / "made" / "mesh.msh", "x"), vesica::Error);
  EXPECT_THROW(write_folder(dir / "made", "history.csv", "x"), vesica::Error);
  EXPECT_EQ(file_text(dir / "made" / "mesh.msh"), "the input");
}

TEST(OutputGuard, AFileAndAFolderNeverReplaceEachOther) {
  const fs::path dir = vesica::test::scratch_dir("guard-kind");
  vesica::write_text_atomically(dir / "out", "a file");
  EXPECT_THROW(write_folder(dir / "out", "x.txt", "x"), vesica::Error);
  EXPECT_EQ(file_text(dir / "out"), "a file");
  write_folder(dir / "folder", "x.txt", "x");
  EXPECT_THROW(vesica::write_text_atomically(dir / "folder", "a file"), vesica::Error);
  EXPECT_EQ(file_text(dir / "folder" / "x.txt"), "x");
}
