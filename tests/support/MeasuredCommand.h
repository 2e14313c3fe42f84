#pragma once
// Runs a shell command with a deadline and measures what it spent: its peak resident
// memory (the largest of it and its children, from wait4's rusage) and its wall time. For
// the tests of hostile inputs: a refusal must come as one line, without gigabytes spent,
// and a case that never answers is killed at the deadline instead of hanging the suite.
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>

namespace vesica::test {

struct MeasuredResult {
  int exit_code = -1;  // 128 + signal when killed
  bool timed_out = false;
  double seconds = 0.0;
  long max_rss_mb = 0;
  std::string output;  // stdout and stderr together
};

inline MeasuredResult run_measured(const std::string& command, int deadline_s = 60) {
  MeasuredResult r;
  char log_name[] = "/tmp/vesica-measured-XXXXXX";
  const int log = ::mkstemp(log_name);
  if (log < 0) return r;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);
    ::dup2(log, 1);
    ::dup2(log, 2);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, WNOHANG, &usage) == 0) {
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(deadline_s)) {
      r.timed_out = true;
      ::kill(-pid, SIGKILL);
      ::wait4(pid, &status, 0, &usage);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  // wait4 reports the shell with the children it waited for: the command's own peak.
  r.max_rss_mb = usage.ru_maxrss / 1024;
  ::lseek(log, 0, SEEK_SET);
  char buffer[4096];
  for (ssize_t n; (n = ::read(log, buffer, sizeof buffer)) > 0;)
    r.output.append(buffer, static_cast<std::size_t>(n));
  ::close(log);
  ::unlink(log_name);
  return r;
}

}  // namespace vesica::test
