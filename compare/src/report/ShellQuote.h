#pragma once
// Internal: a path or word as one single-quoted shell word, for the child processes the
// report starts through std::system (the off-screen renderer, headless chromium).
#include <string>

namespace vesica::compare::detail {

inline std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace vesica::compare::detail
