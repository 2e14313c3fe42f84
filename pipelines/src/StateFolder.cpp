#include "vesica/pipelines/StateFolder.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "vesica/core/Error.h"
#include "vesica/pipelines/PathIndex.h"

namespace vesica::pipelines::state {
namespace {

std::string in_folder(const std::string& name) {
  return std::string(kFolder) + "/" + name;
}

}  // namespace

std::string manifest_path(const std::string& id) {
  return in_folder(id + ".manifest.json");
}
std::string report_path(const std::string& id) {
  return in_folder(id + ".json");
}
std::string failure_path(const std::string& id) {
  return in_folder(id + ".failed.json");
}
std::string lock_path() {
  return in_folder("lock");
}

std::string backup_folder(const std::string& id, const std::string& stamp) {
  return in_folder("backup/" + id + "/" + stamp);
}

void require_state_folder(const std::filesystem::path& workdir) {
  const std::filesystem::path folder = workdir / kFolder;
  std::error_code ec;
  std::filesystem::create_directories(workdir, ec);
  if (::mkdir(folder.c_str(), 0755) != 0 && errno != EEXIST)
    fail(folder.string(), std::string("cannot be made: ") + std::strerror(errno));
  struct stat st {};
  if (::lstat(folder.c_str(), &st) != 0 || !S_ISDIR(st.st_mode))
    fail(folder.string(),
         "is not a folder of vesica's (a link or a file); nothing was written through it",
         "remove it: vesica makes its own");
}

bool is_state_path(const std::string& workdir_relative) {
  return workdir_relative != "." && inside_or_equal(workdir_relative, kFolder);
}

}  // namespace vesica::pipelines::state
