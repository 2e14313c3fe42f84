#include "vesica/pipelines/ChildProcess.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>

#include "vesica/core/Error.h"

namespace vesica::pipelines {

std::string without_escapes(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\033' && i + 1 < text.size() && text[i + 1] == '[') {
      i += 2;
      while (i < text.size() && !std::isalpha(static_cast<unsigned char>(text[i]))) ++i;
      continue;
    }
    out += text[i];
  }
  return out;
}

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
  c_args.reserve(args.size() + 1);
  for (auto& a : args) c_args.push_back(a.data());
  c_args.push_back(nullptr);
  const std::string dir = cwd.string();
  const pid_t parent = ::getpid();

  pid_ = ::fork();
  if (pid_ < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    fail(executable.string(), "cannot fork");
  }
  if (pid_ == 0) {
    ::setpgid(0, 0);
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) ::_exit(129);  // the runner died before prctl took effect
    // Not the terminal's: in a process group of its own, a read from it would stop the stage.
    const int no_input = ::open("/dev/null", O_RDONLY);
    if (no_input >= 0) ::dup2(no_input, STDIN_FILENO);
    ::dup2(fds[1], STDOUT_FILENO);
    ::dup2(fds[1], STDERR_FILENO);
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    ::execv(c_args[0], c_args.data());
    ::_exit(127);
  }
  ::setpgid(pid_, pid_);  // also here: a signal may come before the child ran setpgid
  ::close(fds[1]);
  fd_ = fds[0];
}

ChildProcess::~ChildProcess() {
  if (fd_ >= 0) ::close(fd_);
  if (pid_ > 0) {
    signal_group(SIGTERM);
    wait();
  }
}

bool ChildProcess::read(ChildOutput& out) {
  char buf[4096];
  const ssize_t n = ::read(fd_, buf, sizeof buf);
  if (n < 0 && errno == EINTR) return true;
  if (n <= 0) {
    if (!partial_.empty()) out.lines.push_back(without_escapes(partial_));
    partial_.clear();
    return false;
  }
  for (ssize_t k = 0; k < n; ++k) {
    const char c = buf[k];
    if (c == '\n') {
      out.lines.push_back(without_escapes(partial_));
      partial_.clear();
      redrawing_ = false;
    } else if (c == '\r') {
      partial_.clear();
      redrawing_ = true;
    } else {
      partial_ += c;
    }
  }
  if (redrawing_ && !partial_.empty()) out.progress = without_escapes(partial_);
  return true;
}

void ChildProcess::signal_group(int signal) const {
  if (pid_ > 0) ::kill(-pid_, signal);
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
