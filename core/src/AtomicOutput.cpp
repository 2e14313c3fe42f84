#include "vesica/core/AtomicOutput.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/random.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>

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

bool process_gone(const std::string& pid_text) {
  const long pid = std::strtol(pid_text.c_str(), nullptr, 10);
  return pid > 0 && pid < 1L << 30 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// The process id of a temporary's name ".tmp-<pid>-<random>-<n>-<name>" when that name is
// `name`'s; 0 otherwise. A file name is short (NAME_MAX), but it is scanned, not matched.
long temporary_owner(const std::string& entry, const std::string& name) {
  const std::string prefix = kTemporaryPrefix;
  if (entry.compare(0, prefix.size(), prefix) != 0) return 0;
  std::size_t at = prefix.size();
  long pid = 0;
  for (int field = 0; field < 3; ++field) {  // pid, random, counter: digits, then '-'
    const std::size_t start = at;
    while (at < entry.size() && entry[at] >= '0' && entry[at] <= '9') ++at;
    if (at == start || at - start > 20 || at >= entry.size() || entry[at] != '-') return 0;
    if (field == 0) pid = std::strtol(entry.c_str() + start, nullptr, 10);
    ++at;
  }
  return entry.compare(at, std::string::npos, name) == 0 ? pid : 0;
}

bool process_gone(long pid) {
  return pid > 0 && pid < 1L << 30 && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// Temporaries of `target` whose process no longer runs: a killed run's. Files written
// inside a temporary folder (a series' frames) have no such neighbours.
void remove_stale_temporaries(const fs::path& target) {
  if (detail::inside_temporary(target.parent_path())) return;
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string name = target.filename().string();
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(folder, ec))
    if (process_gone(temporary_owner(e.path().filename().string(), name)))
      fs::remove_all(e.path(), ec);
}

// 64 bits no other user can guess: a temporary's name is never one planted beforehand.
std::uint64_t unpredictable() {
  std::uint64_t r = 0;
  if (::getrandom(&r, sizeof r, 0) != static_cast<ssize_t>(sizeof r))
    r = static_cast<std::uint64_t>(
        std::chrono::steady_clock::now().time_since_epoch().count());  // no entropy device
  return r;
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
  const std::string prefix = kTemporaryPrefix + std::to_string(::getpid()) + "-" +
                             std::to_string(unpredictable()) + "-" + std::to_string(counter++) +
                             "-";
  return target.parent_path() / (prefix + target.filename().string());
}

void write_new_file(const fs::path& path, const std::string& bytes, const fs::path& target) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) fail(target.string(), std::string("could not be created: ") + std::strerror(errno));
  std::size_t done = 0;
  int error = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : ENOSPC;
      break;
    }
    done += static_cast<std::size_t>(n);
  }
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0)
    fail(target.string(), std::string("could not be written: ") + std::strerror(error),
         "check free disk space and permissions");
}

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  write_checked(target, write, false);
}

void require_room_for(const fs::path& target, std::uintmax_t total_bytes,
                      std::uintmax_t largest_file_bytes) {
  detail::check_room(target.has_parent_path() ? target.parent_path() : fs::path("."), total_bytes,
                     largest_file_bytes, target);
}

void write_text_atomically(const fs::path& target, const std::string& text) {
  write_checked(
      target, [&](const fs::path& tmp) { write_new_file(tmp, text, target); }, text.empty());
}

}  // namespace vesica
