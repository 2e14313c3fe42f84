#include "vesica/core/AtomicOutput.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <fstream>
#include <sstream>

#include "TestData.h"
#include "vesica/core/Error.h"

namespace fs = std::filesystem;
using vesica::test::file_text;

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
  EXPECT_EQ(file_text(target), "first");
  // A writer that fails half-way leaves the old content and no temporary behind.
  EXPECT_THROW(vesica::write_atomically(target,
                                        [](const fs::path& tmp) {
                                          std::ofstream(tmp) << "half";
                                          throw vesica::Error(tmp.string(), "boom");
                                        }),
               vesica::Error);
  EXPECT_EQ(file_text(target), "first");
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
  EXPECT_EQ(file_text(target / "x.txt"), "1");
}

TEST(AtomicOutput, FolderNamedWithTrailingSlash) {
  const fs::path dir = vesica::test::scratch_dir("atomic-slash");
  const fs::path target = dir / "ct" / "";  // "…/ct/" as typed on a command line
  EXPECT_EQ(vesica::temporary_sibling(target).parent_path(), dir);
  vesica::write_atomically(target, [&](const fs::path& tmp) {
    fs::create_directories(tmp);
    std::ofstream(tmp / "slice.dcm") << "x";
  });
  EXPECT_EQ(file_text(dir / "ct" / "slice.dcm"), "x");
}

TEST(AtomicOutput, AFullDiskFailsTheWriteAndKeepsTheEarlierFile) {
  const fs::path dir = vesica::test::scratch_dir("atomic-full-disk");
  const fs::path target = dir / "metrics.json";
  vesica::write_text_atomically(target, "earlier");
  // A child process with a 4 KiB file-size limit and SIGXFSZ ignored, as every vesica
  // executable runs: the write fails with EFBIG instead of killing the process.
  const pid_t pid = ::fork();
  if (pid == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
      vesica::write_text_atomically(target, std::string(100000, 'x'));
    } catch (const vesica::Error&) {
      ::_exit(7);
    }
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 7);
  EXPECT_EQ(file_text(target), "earlier");
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir)) (void)e, ++files;
  EXPECT_EQ(files, 1);
}

// tests/support/FailRename.c, linked into this binary, refuses the rename of the named
// output as a full disk would.
TEST(AtomicOutput, AFullDiskAtTheRenameFailsThatOutputOnly) {
  const fs::path dir = vesica::test::scratch_dir("atomic-fault");
  vesica::write_text_atomically(dir / "index.html", "earlier page");
  ::setenv("VESICA_TEST_FAIL_RENAME", "index.html", 1);
  EXPECT_THROW(vesica::write_text_atomically(dir / "index.html", "new page"), vesica::Error);
  vesica::write_text_atomically(dir / "metrics.json", "{}");
  ::unsetenv("VESICA_TEST_FAIL_RENAME");
  EXPECT_EQ(file_text(dir / "index.html"), "earlier page");
  EXPECT_EQ(file_text(dir / "metrics.json"), "{}");
}

TEST(AtomicOutput, TemporariesOfAKilledRunAreRemovedByTheNextWrite) {
  const fs::path dir = vesica::test::scratch_dir("atomic-stale");
  // pid 2^30 - 1 is above any pid Linux hands out: that process is gone.
  const fs::path stale = dir / ".tmp-1073741823-5-0-sim";
  fs::create_directories(stale);
  std::ofstream(stale / "step_0000.vtu") << "half";
  const fs::path other = dir / ".tmp-1073741823-5-1-other.txt";  // another output's
  std::ofstream(other) << "x";
  vesica::write_atomically(dir / "sim", [](const fs::path& tmp) {
    fs::create_directories(tmp);
    std::ofstream(tmp / "history.csv") << "t\n";
  });
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(other));
}

TEST(AtomicOutput, AnEmptyResultIsAnError) {
  const fs::path dir = vesica::test::scratch_dir("atomic-empty");
  EXPECT_THROW(vesica::write_atomically(dir / "a.vtp",
                                        [](const fs::path& tmp) {
                                          std::ofstream{tmp};  // a writer that failed silently
                                        }),
               vesica::Error);
  EXPECT_FALSE(fs::exists(dir / "a.vtp"));
}
