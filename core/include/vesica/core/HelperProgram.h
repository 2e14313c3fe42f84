#pragma once
// Helper programs vesica starts (the off-screen renderer under xvfb-run, headless chromium)
// run without a shell: the program is found on PATH and executed with an argument vector,
// and its output goes to a file that vesica itself opened inside a folder of its own. A
// quote in a path, a planted link or a name another user chose beforehand in the shared
// temporary folder can then change nothing but the helper's arguments.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vesica {

// A fresh folder under $TMPDIR (else /tmp) that only this process can have made
// (mkdtemp: a new name, created with mode 0700, never an existing folder), removed with
// everything in it when the object goes.
class TemporaryFolder {
 public:
  // `purpose` becomes part of the name ("vesica-compare-XXXXXX"). Throws vesica::Error
  // when no folder can be made.
  explicit TemporaryFolder(const std::string& purpose);
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// The executable `name` on PATH (as a shell's `command -v` finds it), or nothing.
std::optional<std::filesystem::path> find_program(const std::string& name);

struct HelperResult {
  int exit_code = -1;      // 128 + signal when killed; -1 when it could not start
  bool timed_out = false;  // stopped at the deadline
  std::string output;      // the last kMaxHelperOutput bytes of stdout and stderr, merged
};

inline constexpr std::size_t kMaxHelperOutput = 4096;

// Runs argv[0] (a path, or a name looked up on PATH) with argv, stdin from /dev/null and
// stdout + stderr into `log`, a new file opened with O_EXCL | O_NOFOLLOW (it must not
// exist: put it in a TemporaryFolder). The helper leads a process group of its own; at the
// deadline the group gets SIGTERM, then SIGKILL two seconds later.
HelperResult run_helper(const std::vector<std::string>& argv, const std::filesystem::path& log,
                        std::chrono::seconds deadline);

}  // namespace vesica
