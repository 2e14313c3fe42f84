#pragma once
// Internal: ASCII lower case, for extensions, column names and segment names, which
// vesica matches without regard to case.
#include <algorithm>
#include <cctype>
#include <string>

namespace vesica::io::detail {

inline std::string lower_case(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

}  // namespace vesica::io::detail
