#pragma once
// Workdir-relative paths (normal form, "a/b") with a value each, asked "which entry is this
// path or a folder holding it" and "which entry lies inside this folder" in O(log n) per
// component, so that checking a pipeline of n stages stays O(n log n) instead of comparing
// every output with every other one.
#include <map>
#include <string>

namespace vesica::pipelines {

class PathIndex {
 public:
  // Keeps the first value added for a path.
  void add(const std::string& path, long value);
  // The value of `path` itself or of the nearest entry that is a folder holding it; -1
  // when there is none.
  long holder_of(const std::string& path) const;
  // An entry equal to `folder` or inside it ("." holds everything), as (path, value); an
  // empty path when there is none.
  std::pair<std::string, long> inside(const std::string& folder) const;
  bool empty() const { return entries_.empty(); }

 private:
  std::map<std::string, long> entries_;
};

// True when `path` is `folder` or lies inside it (both workdir-relative normal forms; "."
// holds everything).
bool inside_or_equal(const std::string& path, const std::string& folder);

}  // namespace vesica::pipelines
