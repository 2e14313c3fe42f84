#include "vesica/core/AtomicOutput.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>

#include "OutputCheck.h"
#include "OutputInstall.h"
#include "vesica/core/Error.h"
#include "vesica/core/StagedOutputs.h"

namespace fs = std::filesystem;

namespace vesica {
namespace {

constexpr const char* kTemporaryPrefix = ".tmp-";

// "out/ct/" names the folder "out/ct": drop trailing separators so that the temporary is a
// sibling of the folder, not a file inside it.
fs::path without_trailing_separator(const fs::path& p) {
  fs::path t = p.lexically_normal();
  while (!t.empty() && !t.has_filename() && t.has_parent_path() && t != t.root_path())
    t = t.parent_path();
  return t;
}

void fsync_tree(const fs::path& p, const fs::path& target) {
  if (fs::is_directory(p))
    for (const auto& e : fs::recursive_directory_iterator(p))
      detail::flush_to_disk(e.path(), target);
  detail::flush_to_disk(p, target);
}

void check_not_empty(const fs::path& tmp, const fs::path& target) {
  std::error_code ec;
  if (!fs::exists(tmp, ec)) fail(target.string(), "the writer produced no output");
  if (fs::is_regular_file(tmp, ec) && fs::file_size(tmp, ec) == 0)
    fail(target.string(), "the writer produced an empty file");
  if (fs::is_directory(tmp, ec) && fs::is_empty(tmp, ec))
    fail(target.string(), "the writer produced an empty folder");
}

void injected_fault(const fs::path& target) {
  const char* pattern = std::getenv("VESICA_FAIL_WRITE");
  if (pattern && *pattern && target.filename().string().find(pattern) != std::string::npos)
    fail(target.string(),
         "could not be written: no space left on device (simulated by VESICA_FAIL_WRITE)");
}

bool process_gone(const std::string& pid_text) {
  const long pid = std::strtol(pid_text.c_str(), nullptr, 10);
  return pid > 0 && pid < 1L << 30 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// ".tmp-<pid>-<stamp>-<n>-<name>" of a process that no longer runs: a killed run's. Files
// written inside a temporary folder (a series' frames) have no such neighbours.
void remove_stale_temporaries(const fs::path& target) {
  if (detail::inside_temporary(target.parent_path())) return;
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string name = target.filename().string();
  static const std::regex pattern(R"(\.tmp-(\d+)-\d+-\d+-(.*))");
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    const std::string entry = e.path().filename().string();
    std::smatch m;
    if (entry.rfind(kTemporaryPrefix, 0) != 0 || !std::regex_match(entry, m, pattern)) continue;
    if (m[2].str() == name && process_gone(m[1].str())) fs::remove_all(e.path(), ec);
  }
}

void write_checked(const fs::path& target_given, const std::function<void(const fs::path&)>& write,
                   bool may_be_empty) {
  if (staging())
    if (const auto place = place_in_staged_folder(target_given))
      return write_checked(*place, write, may_be_empty);  // committed with its folder
  const fs::path target = without_trailing_separator(target_given);
  require_replaceable(target, OutputKind::Either);
  try {
    if (target.has_parent_path()) fs::create_directories(target.parent_path());
  } catch (const fs::filesystem_error& e) {
    fail(target.string(), "its folder cannot be created: " + e.code().message());
  }
  remove_stale_temporaries(target);
  const fs::path tmp = temporary_sibling(target);
  try {
    write(tmp);
    if (!may_be_empty) check_not_empty(tmp, target);
    const bool folder = fs::is_directory(tmp);
    if (folder) write_folder_marker(tmp);
    fsync_tree(tmp, target);
    detail::check_written(tmp, target);
    injected_fault(target);
    require_replaceable(target, folder ? OutputKind::Folder : OutputKind::File);
    if (staging() && !detail::inside_temporary(target.parent_path()))
      stage_output(tmp, target);
    else
      detail::install_output(tmp, target);
  } catch (const fs::filesystem_error& e) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    fail(target.string(), "could not be written: " + e.code().message());
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace

fs::path temporary_sibling(const fs::path& target_given) {
  const fs::path target = without_trailing_separator(target_given);
  static std::atomic<unsigned> counter{0};
  const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
  const std::string prefix = kTemporaryPrefix + std::to_string(::getpid()) + "-" +
                             std::to_string(stamp % 1000000) + "-" + std::to_string(counter++) +
                             "-";
  return target.parent_path() / (prefix + target.filename().string());
}

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  write_checked(target, write, false);
}

void write_text_atomically(const fs::path& target, const std::string& text) {
  write_checked(
      target,
      [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out << text;
        out.close();
        std::error_code ec;
        if (!out || fs::file_size(tmp, ec) != text.size())
          fail(target.string(), "could not be written", "check free disk space and permissions");
      },
      text.empty());
}

}  // namespace vesica
