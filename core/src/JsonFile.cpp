#include "vesica/core/JsonFile.h"

namespace vesica {
namespace {

// vesica's files nest a few levels; nlohmann's dump() and comparisons recurse once per
// level, so a file nested deeper is refused before it is parsed.
constexpr int kMaxJsonDepth = 64;

bool nested_too_deep(const std::string& text) {
  int depth = 0;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\')
        ++i;
      else if (c == '"')
        in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth) return true;
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
  return false;
}

}  // namespace

std::optional<nlohmann::json> read_json_file(const std::filesystem::path& path,
                                             std::uintmax_t max_bytes) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return std::nullopt;
  const std::string text = read_input_file(path, max_bytes, "JSON file");
  if (nested_too_deep(text)) return nlohmann::json(nlohmann::json::value_t::discarded);
  return nlohmann::json::parse(text, nullptr, false);
}

}  // namespace vesica
