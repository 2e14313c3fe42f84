#pragma once
// Helpers for the runner tests: write a pipeline file, run the real `vesica` binary and
// read back its exit code, stdout and stderr.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "TestData.h"

namespace vesica::test {

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline void write_text(const std::filesystem::path& p, const std::string& text) {
  if (p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << text;
}

inline std::string quoted(const std::string& s) {
  return "'" + s + "'";
}

// Runs a shell command line, capturing stdout and stderr into files beside `scratch`.
inline CommandResult run_command(const std::string& command, const std::filesystem::path& scratch) {
  const auto out = scratch / "cmd.out", err = scratch / "cmd.err";
  const int status = std::system(
      (command + " >" + quoted(out.string()) + " 2>" + quoted(err.string()) + " </dev/null")
          .c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

inline CommandResult run_vesica(const std::string& args, const std::filesystem::path& scratch) {
  return run_command(quoted((bin_dir() / "vesica").string()) + " " + args, scratch);
}

// `vesica run FILE --json` and the ids of the stages that ran.
inline std::vector<std::string> run_json(const std::filesystem::path& file,
                                         const std::filesystem::path& scratch,
                                         const std::string& extra = "", int* exit_code = nullptr) {
  const CommandResult r = run_vesica("run " + quoted(file.string()) + " --json " + extra, scratch);
  if (exit_code) *exit_code = r.exit_code;
  const auto j = nlohmann::json::parse(r.out, nullptr, false);
  if (j.is_discarded()) return {"<no JSON: " + r.err + ">"};
  return j["ran"].get<std::vector<std::string>>();
}

// stage id -> {state, reason} from `vesica status --json`.
inline std::map<std::string, std::pair<std::string, std::string>> status_of(
    const std::filesystem::path& file, const std::filesystem::path& scratch) {
  const CommandResult r = run_vesica("status " + quoted(file.string()) + " --json", scratch);
  std::map<std::string, std::pair<std::string, std::string>> m;
  const auto j = nlohmann::json::parse(r.out, nullptr, false);
  if (j.is_discarded()) return m;
  for (const auto& s : j) m[s["stage"]] = {s["state"], s["reason"]};
  return m;
}

using Ids = std::vector<std::string>;

// Starts `vesica run FILE` in the background, its stderr to `err`; returns its PID.
inline pid_t start_run(const std::filesystem::path& file, const std::filesystem::path& err) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const std::string vesica = (bin_dir() / "vesica").string();
    std::freopen(err.c_str(), "w", stderr);
    std::freopen("/dev/null", "w", stdout);
    ::execl(vesica.c_str(), vesica.c_str(), "run", file.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  return pid;
}

// Its exit status, 128 + signal when a signal ended it.
inline int wait_exit(pid_t pid) {
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace vesica::test
