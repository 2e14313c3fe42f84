#include "vesica/core/HelperProgram.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

#include "vesica/core/Error.h"

namespace fs = std::filesystem;

namespace vesica {
namespace {

using Clock = std::chrono::steady_clock;

// The exit code of a wait status: 128 + signal when killed.
int exit_code_of(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

// Waits for `pid` until `until`; true when it ended (its code in `code`).
bool wait_until(pid_t pid, Clock::time_point until, int& code) {
  while (true) {
    int status = 0;
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) {
      code = exit_code_of(status);
      return true;
    }
    if (r < 0 && errno != EINTR) {
      code = -1;
      return true;
    }
    if (Clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

std::string tail_of(const fs::path& log) {
  std::ifstream in(log, std::ios::binary | std::ios::ate);
  if (!in) return {};
  const std::streamoff size = in.tellg();
  const std::streamoff from =
      size > static_cast<std::streamoff>(kMaxHelperOutput) ? size - kMaxHelperOutput : 0;
  in.seekg(from);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

TemporaryFolder::TemporaryFolder(const std::string& purpose) {
  const char* tmpdir = std::getenv("TMPDIR");
  const fs::path base = tmpdir && *tmpdir ? fs::path(tmpdir) : fs::path("/tmp");
  std::string pattern = (base / ("vesica-" + purpose + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
    fail(base.string(), std::string("cannot make a temporary folder: ") + std::strerror(errno),
         "set TMPDIR to a writable folder");
  path_ = pattern;
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ec;
  fs::remove_all(path_, ec);
}

std::optional<fs::path> find_program(const std::string& name) {
  if (name.find('/') != std::string::npos)
    return ::access(name.c_str(), X_OK) == 0 ? std::optional<fs::path>(name) : std::nullopt;
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const fs::path candidate = fs::path(dir.empty() ? "." : dir) / name;
    std::error_code ec;
    if (fs::is_regular_file(candidate, ec) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
  }
  return std::nullopt;
}

HelperResult run_helper(const std::vector<std::string>& argv, const fs::path& log,
                        std::chrono::seconds deadline) {
  HelperResult result;
  if (argv.empty()) return result;
  const auto program = find_program(argv[0]);
  if (!program) {
    result.output = argv[0] + ": not found";
    return result;
  }
  const int out = ::open(log.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (out < 0) fail(log.string(), std::string("cannot be created: ") + std::strerror(errno));
  // Everything the child needs is made before fork: only async-signal-safe calls after.
  std::vector<std::string> args = argv;
  std::vector<char*> c_args;
  for (auto& a : args) c_args.push_back(a.data());
  c_args.push_back(nullptr);
  const std::string executable = program->string();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(out);
    fail(executable, "cannot start: fork failed");
  }
  if (pid == 0) {
    ::setpgid(0, 0);
    const int no_input = ::open("/dev/null", O_RDONLY);
    if (no_input >= 0) ::dup2(no_input, STDIN_FILENO);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(out, STDERR_FILENO);
    ::execv(executable.c_str(), c_args.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also here: the deadline may come before the child ran setpgid
  ::close(out);
  if (!wait_until(pid, Clock::now() + deadline, result.exit_code)) {
    result.timed_out = true;
    ::kill(-pid, SIGTERM);
    if (!wait_until(pid, Clock::now() + std::chrono::seconds(2), result.exit_code)) {
      ::kill(-pid, SIGKILL);
      wait_until(pid, Clock::time_point::max(), result.exit_code);
    }
  }
  result.output = tail_of(log);
  return result;
}

}  // namespace vesica
