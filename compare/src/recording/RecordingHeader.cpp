#include "vesica/compare/recording/RecordingHeader.h"

#include <fstream>
#include <regex>

namespace vesica::compare {
namespace {

// Header lines are free text: every pattern ignores case.
std::regex pattern(const char* text) {
  return std::regex(text, std::regex::ECMAScript | std::regex::icase);
}

// "sex: f", "gender = male"; else the words of free text. Both sexes named: unknown.
Sex sex_of(const std::string& text) {
  std::smatch m;
  if (std::regex_search(text, m, pattern(R"((?:sex|gender)\s*[:=]\s*([a-z]+))")))
    return sex_from_word(m[1]);
  const bool female = std::regex_search(text, pattern(R"(\b(female|woman|women)\b)"));
  const bool male = std::regex_search(text, pattern(R"(\b(male|man|men)\b)"));
  if (female == male) return Sex::unknown;
  return female ? Sex::female : Sex::male;
}

std::optional<double> age_of(const std::string& text) {
  std::smatch m;
  if (std::regex_search(text, m, pattern(R"(\bage\s*[:=]?\s*(\d{1,3})\b)")) ||
      std::regex_search(text, m, pattern(R"(\b(\d{1,3})\s*-?\s*(?:years?|yrs?|y)\b)")))
    return std::stod(m[1]);
  return std::nullopt;
}

std::optional<double> fill_rate_of(const std::string& text) {
  std::smatch m;
  if (std::regex_search(text, m, pattern(R"((\d+(?:\.\d+)?)\s*ml\s*/\s*min)")))
    return std::stod(m[1]);
  return std::nullopt;
}

}  // namespace

RecordingHeader parse_recording_header(const std::vector<std::string>& lines) {
  RecordingHeader h;
  for (const std::string& line : lines) {
    if (h.sex == Sex::unknown) h.sex = sex_of(line);
    if (!h.age_years) h.age_years = age_of(line);
    if (!h.stated_fill_rate_ml_min) h.stated_fill_rate_ml_min = fill_rate_of(line);
  }
  return h;
}

RecordingHeader read_recording_header(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    const auto start = line.find_first_not_of(" \t\xEF\xBB\xBF");  // a byte-order mark too
    if (start == std::string::npos) continue;
    if (line[start] != '#') break;  // the column header: the comments are over
    lines.push_back(line.substr(start + 1));
  }
  return parse_recording_header(lines);
}

}  // namespace vesica::compare
