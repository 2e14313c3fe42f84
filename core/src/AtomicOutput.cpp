#include "vesica/core/AtomicOutput.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <fstream>

#include "vesica/core/Error.h"

namespace fs = std::filesystem;

namespace vesica {
namespace {

// "out/ct/" names the folder "out/ct": drop trailing separators so that the temporary is a
// sibling of the folder, not a file inside it.
fs::path without_trailing_separator(const fs::path& p) {
  fs::path t = p.lexically_normal();
  while (!t.empty() && !t.has_filename() && t.has_parent_path() && t != t.root_path())
    t = t.parent_path();
  return t;
}

void fsync_path(const fs::path& p) {
  int fd = ::open(p.c_str(), O_RDONLY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

void fsync_tree(const fs::path& p) {
  if (fs::is_directory(p)) {
    for (const auto& e : fs::recursive_directory_iterator(p)) fsync_path(e.path());
  }
  fsync_path(p);
}

}  // namespace

fs::path temporary_sibling(const fs::path& target_given) {
  const fs::path target = without_trailing_separator(target_given);
  static std::atomic<unsigned> counter{0};
  const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
  const std::string prefix = ".tmp-" + std::to_string(::getpid()) + "-" +
                             std::to_string(stamp % 1000000) + "-" +
                             std::to_string(counter++) + "-";
  return target.parent_path() / (prefix + target.filename().string());
}

void write_atomically(const fs::path& target_given,
                      const std::function<void(const fs::path&)>& write) {
  const fs::path target = without_trailing_separator(target_given);
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  const fs::path tmp = temporary_sibling(target);
  try {
    write(tmp);
    if (!fs::exists(tmp)) fail(target.string(), "writer produced no output");
    fsync_tree(tmp);
    std::error_code ec;
    if (fs::is_directory(tmp) && fs::exists(target)) fs::remove_all(target, ec);
    fs::rename(tmp, target);
    if (target.has_parent_path()) fsync_path(target.parent_path());
  } catch (...) {
    std::error_code ec;
    fs::remove_all(tmp, ec);
    throw;
  }
}

void write_text_atomically(const fs::path& target, const std::string& text) {
  write_atomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) fail(target.string(), "could not write", "check free disk space and permissions");
  });
}

}  // namespace vesica
