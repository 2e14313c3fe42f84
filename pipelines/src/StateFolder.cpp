#include "vesica/pipelines/StateFolder.h"

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

bool is_state_path(const std::string& workdir_relative) {
  return workdir_relative != "." && inside_or_equal(workdir_relative, kFolder);
}

}  // namespace vesica::pipelines::state
