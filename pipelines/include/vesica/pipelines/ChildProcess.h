#pragma once
// One stage command running as a child process (fork/exec, waitpid) whose stdout and
// stderr arrive, merged, on a pipe the runner reads. The child leads a process group of its
// own, so that a signal meant for the runner (Ctrl-C on the terminal) reaches the stage
// only through the runner, which passes it on and then waits for the stage to end; and it
// is sent SIGTERM if the runner dies without doing so (Linux's parent-death signal).
#include <sys/types.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace vesica::pipelines {

// What one read of the pipe brought: complete lines, and the latest progress line: text a
// stage redraws in place with '\r' (vesica::Progress), without its terminal escapes.
struct ChildOutput {
  std::vector<std::string> lines;
  std::optional<std::string> progress;
};

class ChildProcess {
 public:
  // Starts `executable argv...` in folder `cwd`. Throws vesica::Error when it cannot start.
  ChildProcess(const std::filesystem::path& executable, const std::vector<std::string>& argv,
               const std::filesystem::path& cwd);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  int output_fd() const { return fd_; }
  // Reads what is available into `out`. Returns false at EOF.
  bool read(ChildOutput& out);
  // Sends `signal` to the child's process group (the stage and anything it started).
  void signal_group(int signal) const;
  // Waits for the process; returns its exit code (128 + signal when killed).
  int wait();

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string partial_;
  bool redrawing_ = false;  // partial_ follows a '\r': a progress line being redrawn
};

// `text` without terminal escape sequences (ESC [ ... letter).
std::string without_escapes(const std::string& text);

}  // namespace vesica::pipelines
