#include "vesica/pipelines/PathIndex.h"

namespace vesica::pipelines {

bool inside_or_equal(const std::string& path, const std::string& folder) {
  if (folder == ".") return true;
  return path == folder ||
         (path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
          path[folder.size()] == '/');
}

void PathIndex::add(const std::string& path, long value) {
  entries_.emplace(path, value);
}

long PathIndex::holder_of(const std::string& path) const {
  if (const auto all = entries_.find("."); all != entries_.end()) return all->second;
  std::string p = path;
  while (!p.empty()) {
    if (const auto it = entries_.find(p); it != entries_.end()) return it->second;
    const auto slash = p.find_last_of('/');
    if (slash == std::string::npos || slash == 0) break;
    p.resize(slash);
  }
  return -1;
}

std::pair<std::string, long> PathIndex::inside(const std::string& folder) const {
  if (folder == "." && !entries_.empty()) return *entries_.begin();
  if (const auto it = entries_.find(folder); it != entries_.end()) return *it;
  // Every path under "folder/" sorts in one run starting at "folder/".
  const std::string prefix = folder + "/";
  const auto it = entries_.lower_bound(prefix);
  if (it != entries_.end() && it->first.compare(0, prefix.size(), prefix) == 0) return *it;
  return {"", -1};
}

}  // namespace vesica::pipelines
