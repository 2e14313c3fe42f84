#include "vesica/core/AtomicOutput.h"

#include <fstream>
#include <sstream>

#include "TestData.h"
#include "vesica/core/Error.h"

namespace fs = std::filesystem;

namespace {
std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}
}  // namespace

TEST(AtomicOutput, TemporaryKeepsExtensionAndFolder) {
  const fs::path tmp = vesica::temporary_sibling("out/dir/bladder.nii.gz");
  EXPECT_EQ(tmp.parent_path(), fs::path("out/dir"));
  const std::string name = tmp.filename().string();
  EXPECT_EQ(name.substr(name.size() - 14), "bladder.nii.gz");
  EXPECT_EQ(name.front(), '.');
}

TEST(AtomicOutput, ReplacesOnlyWhenComplete) {
  const fs::path dir = vesica::test::scratch_dir("atomic");
  const fs::path target = dir / "a.txt";
  vesica::write_text_atomically(target, "first");
  EXPECT_EQ(read(target), "first");
  // A writer that fails half-way leaves the old content and no temporary behind.
  EXPECT_THROW(vesica::write_atomically(target,
                                        [](const fs::path& tmp) {
                                          std::ofstream(tmp) << "half";
                                          throw vesica::Error(tmp.string(), "boom");
                                        }),
               vesica::Error);
  EXPECT_EQ(read(target), "first");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) (void)e, ++files;
  EXPECT_EQ(files, 1);
}

TEST(AtomicOutput, WritesFolders) {
  const fs::path dir = vesica::test::scratch_dir("atomic-dir");
  const fs::path target = dir / "series";
  for (int round = 0; round < 2; ++round) {
    vesica::write_atomically(target, [&](const fs::path& tmp) {
      fs::create_directories(tmp);
      std::ofstream(tmp / "x.txt") << round;
    });
  }
  EXPECT_EQ(read(target / "x.txt"), "1");
}

TEST(AtomicOutput, FolderNamedWithTrailingSlash) {
  const fs::path dir = vesica::test::scratch_dir("atomic-slash");
  const fs::path target = dir / "ct" / "";  // "…/ct/" as typed on a command line
  EXPECT_EQ(vesica::temporary_sibling(target).parent_path(), dir);
  vesica::write_atomically(target, [&](const fs::path& tmp) {
    fs::create_directories(tmp);
    std::ofstream(tmp / "slice.dcm") << "x";
  });
  EXPECT_EQ(read(dir / "ct" / "slice.dcm"), "x");
}
