#include "vesica/pipelines/ChildProcess.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "vesica/core/Error.h"

namespace vesica::pipelines {

ChildProcess::ChildProcess(const std::filesystem::path& executable,
                           const std::vector<std::string>& argv, const std::filesystem::path& cwd) {
  if (::access(executable.c_str(), X_OK) != 0)
    fail(executable.string(), "stage executable not found or not executable",
         "build it first (cmake --build ... --target " + executable.filename().string() + ")");
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) fail(executable.string(), "cannot create a pipe");
  // Everything the child needs is prepared before fork: only async-signal-safe calls after.
  std::vector<std::string> args = {executable.string()};
  args.insert(args.end(), argv.begin(), argv.end());
  std::vector<char*> c_args;
  for (auto& a : args) c_args.push_back(a.data());
  c_args.push_back(nullptr);
  const std::string dir = cwd.string();

  pid_ = ::fork();
  if (pid_ < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    fail(executable.string(), "cannot fork");
  }
  if (pid_ == 0) {
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::execv(c_args[0], c_args.data());
    ::_exit(127);
  }
  ::close(fds[1]);
  fd_ = fds[0];
}

ChildProcess::~ChildProcess() {
  if (fd_ >= 0) ::close(fd_);
  if (pid_ > 0) wait();
}

bool ChildProcess::read_lines(std::vector<std::string>& lines) {
  char buf[4096];
  const ssize_t n = ::read(fd_, buf, sizeof buf);
  if (n < 0 && errno == EINTR) return true;
  if (n <= 0) {
    if (!partial_.empty()) lines.push_back(partial_);
    partial_.clear();
    return false;
  }
  partial_.append(buf, static_cast<std::size_t>(n));
  for (auto nl = partial_.find('\n'); nl != std::string::npos; nl = partial_.find('\n')) {
    lines.push_back(partial_.substr(0, nl));
    partial_.erase(0, nl + 1);
  }
  return true;
}

int ChildProcess::wait() {
  if (pid_ <= 0) return -1;
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return 1;
}

}  // namespace vesica::pipelines
