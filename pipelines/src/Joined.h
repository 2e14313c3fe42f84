#pragma once
// Internal to vesica_pipelines: "a, b, c", the way messages list files and stages.
#include <string>
#include <vector>

namespace vesica::pipelines::detail {

inline std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

}  // namespace vesica::pipelines::detail
