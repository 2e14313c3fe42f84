#include "OutputCheck.h"

#include <sys/resource.h>
#include <sys/statvfs.h>
#include <unistd.h>
#include <zlib.h>

#include <array>

#include "vesica/core/Error.h"

namespace fs = std::filesystem;

namespace vesica::detail {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

void check_size_limit(const fs::path& file, const fs::path& target) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_FSIZE, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return;
  std::error_code ec;
  if (fs::file_size(file, ec) >= limit.rlim_cur && !ec)
    fail(target.string(), "could not be written whole: it reached the file-size limit of " +
                              std::to_string(limit.rlim_cur) + " bytes (ulimit -f)");
}

void check_free_space(const fs::path& folder, const fs::path& target) {
  struct statvfs s {};
  if (::statvfs(folder.c_str(), &s) != 0) return;
  const auto free_blocks = ::geteuid() == 0 ? s.f_bfree : s.f_bavail;
  if (free_blocks == 0 && s.f_blocks > 0)
    fail(target.string(), "could not be written whole: the disk is full",
         "free some space and run again");
}

void check_gzip(const fs::path& file, const fs::path& target) {
  gzFile gz = ::gzopen(file.c_str(), "rb");
  if (!gz) fail(target.string(), "could not be reopened to check it");
  std::array<char, 1 << 16> buffer{};
  int got = 0;
  while ((got = ::gzread(gz, buffer.data(), buffer.size())) > 0) {
  }
  int error = Z_OK;
  const char* message = ::gzerror(gz, &error);
  const std::string why = message ? message : "";
  ::gzclose(gz);
  if (got < 0 || error != Z_OK)
    fail(target.string(), "was written cut or corrupt (its gzip stream: " + why + ")",
         "check free disk space and quotas");
}

void check_file(const fs::path& file, const fs::path& target) {
  check_size_limit(file, target);
  if (ends_with(file.filename().string(), ".gz")) check_gzip(file, target);
}

}  // namespace

void check_written(const fs::path& written, const fs::path& target) {
  if (fs::is_directory(written)) {
    for (const auto& e : fs::recursive_directory_iterator(written))
      if (e.is_regular_file()) check_file(e.path(), target);
  } else {
    check_file(written, target);
  }
  check_free_space(written.parent_path().empty() ? fs::path(".") : written.parent_path(), target);
}

void check_room(const fs::path& folder, std::uintmax_t total_bytes,
                std::uintmax_t largest_file_bytes, const fs::path& target) {
  rlimit limit{};
  if (::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      largest_file_bytes >= limit.rlim_cur)
    fail(target.string(), "cannot be written: a file of it needs " +
                              std::to_string(largest_file_bytes) +
                              " bytes, above the file-size "
                              "limit of " +
                              std::to_string(limit.rlim_cur) + " (ulimit -f)");
  fs::path existing = fs::absolute(folder);
  std::error_code ec;
  while (!fs::exists(existing, ec) && existing.has_parent_path() &&
         existing != existing.root_path())
    existing = existing.parent_path();
  struct statvfs s {};
  if (::statvfs(existing.c_str(), &s) != 0) return;
  const std::uintmax_t free_bytes =
      static_cast<std::uintmax_t>(::geteuid() == 0 ? s.f_bfree : s.f_bavail) * s.f_frsize;
  if (free_bytes < total_bytes)
    fail(target.string(),
         "cannot be written: it needs about " + std::to_string(total_bytes) +
             " bytes, the disk has " + std::to_string(free_bytes) + " free",
         "free some space and run again");
}

}  // namespace vesica::detail
