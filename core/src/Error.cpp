#include "vesica/core/Error.h"

#include "vesica/core/UidScrub.h"

namespace vesica {
namespace {

std::string one_line(const std::string& file, const std::string& problem, const std::string& hint) {
  std::string s = file.empty() ? problem : file + ": " + problem;
  if (!hint.empty()) s += " (" + hint + ")";
  return single_line(without_uids(s));
}

bool utf8_continuation(char c) {
  return (static_cast<unsigned char>(c) & 0xC0) == 0x80;
}

}  // namespace

std::string single_line(const std::string& text, std::size_t max_chars) {
  std::string s = text;
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = ' ';
  if (s.size() <= max_chars) return s;
  const std::string ellipsis = "...";
  std::size_t cut = max_chars > ellipsis.size() ? max_chars - ellipsis.size() : 0;
  while (cut > 0 && utf8_continuation(s[cut])) --cut;  // never split a character
  return s.substr(0, cut) + ellipsis;
}

Error::Error(std::string file, std::string problem, std::string hint, Kind kind)
    : std::runtime_error(one_line(file, problem, hint)),
      file_(std::move(file)),
      problem_(std::move(problem)),
      hint_(std::move(hint)),
      kind_(kind) {}

void fail(const std::string& file, const std::string& problem, const std::string& hint) {
  throw Error(file, problem, hint, Error::Kind::Failure);
}

void usage_error(const std::string& problem, const std::string& hint) {
  throw Error("", problem, hint, Error::Kind::Usage);
}

}  // namespace vesica
