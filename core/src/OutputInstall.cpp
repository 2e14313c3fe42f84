#include "OutputInstall.h"

#include <fcntl.h>
#include <stdio.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"

namespace fs = std::filesystem;

namespace vesica::detail {
namespace {

constexpr const char* kTemporaryPrefix = ".tmp-";

// A folder replaces a folder in one step (the two names are exchanged, then the old
// content removed); where the file system cannot exchange, the old folder is moved aside
// and moved back should the second rename fail.
void replace_folder(const fs::path& tmp, const fs::path& target) {
  if (::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
    std::error_code ec;
    fs::remove_all(tmp, ec);  // now the earlier output, checked replaceable
    return;
  }
  const fs::path aside = temporary_sibling(target);
  fs::rename(target, aside);
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::rename(aside, target);
    fail(target.string(), "could not be replaced: " + ec.message());
  }
  fs::remove_all(aside, ec);
}

}  // namespace

void install_output(const fs::path& tmp, const fs::path& target) {
  try {
    std::error_code ec;
    if (fs::is_directory(tmp) && fs::is_directory(fs::symlink_status(target, ec)))
      replace_folder(tmp, target);
    else
      fs::rename(tmp, target);
  } catch (const fs::filesystem_error& e) {
    fail(target.string(), "could not be renamed into place: " + e.code().message());
  }
  flush_to_disk(target.has_parent_path() ? target.parent_path() : fs::path("."), target);
}

void flush_to_disk(const fs::path& path, const fs::path& target) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    fail(target.string(),
         std::string("could not be reopened to flush it: ") + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  if (rc != 0 && error != EINVAL)
    fail(target.string(), std::string("could not be written: ") + std::strerror(error),
         "check free disk space and quotas");
}

bool inside_temporary(const fs::path& path) {
  for (const auto& part : path)
    if (part.string().rfind(kTemporaryPrefix, 0) == 0) return true;
  return false;
}

fs::path output_key(const fs::path& target) {
  fs::path key = fs::absolute(target).lexically_normal();
  while (!key.has_filename() && key.has_parent_path() && key != key.root_path())
    key = key.parent_path();
  return key;
}

}  // namespace vesica::detail
