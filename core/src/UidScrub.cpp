#include "vesica/core/UidScrub.h"

#include <cctype>

#include "vesica/core/ContentHash.h"

namespace vesica {
namespace {

constexpr std::size_t kMinUidChars = 16;
constexpr int kMinUidDots = 2;

bool digit(char c) {
  return c >= '0' && c <= '9';
}

bool word_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0;
}

// Whether text[b, e) (digits and dots) reads as a UID.
bool uid_like(const std::string& text, std::size_t b, std::size_t e) {
  if (e - b < kMinUidChars || !digit(text[b]) || !digit(text[e - 1])) return false;
  int dots = 0;
  for (std::size_t i = b; i < e; ++i) {
    if (text[i] != '.') continue;
    if (text[i + 1] == '.') return false;  // "1..2" is no UID
    ++dots;
  }
  return dots >= kMinUidDots;
}

}  // namespace

std::string without_uids(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    if (!digit(text[i]) || (i > 0 && word_char(text[i - 1]))) {
      out += text[i++];
      continue;
    }
    std::size_t e = i;
    while (e < text.size() && (digit(text[e]) || text[e] == '.')) ++e;
    std::size_t end = e;
    while (end > i && text[end - 1] == '.') --end;  // a sentence's full stop is not the UID's
    const bool alone = end == text.size() || !word_char(text[end]);  // ".dcm" may follow
    if (alone && uid_like(text, i, end))
      out += "uid-" + sha256_hex(text.substr(i, end - i)).substr(0, 8);
    else
      out.append(text, i, end - i);
    i = end;
  }
  return out;
}

}  // namespace vesica
