#pragma once
// One stage command running as a child process (fork/exec, waitpid) whose stdout and
// stderr arrive, merged, on a pipe the runner reads line by line.
#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace vesica::pipelines {

class ChildProcess {
 public:
  // Starts `executable argv...` in folder `cwd`. Throws vesica::Error when it cannot start.
  ChildProcess(const std::filesystem::path& executable, const std::vector<std::string>& argv,
               const std::filesystem::path& cwd);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  int output_fd() const { return fd_; }
  // Reads what is available; complete lines are appended to `lines`. Returns false at EOF.
  bool read_lines(std::vector<std::string>& lines);
  // Waits for the process; returns its exit code (128 + signal when killed).
  int wait();

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string partial_;
};

}  // namespace vesica::pipelines
