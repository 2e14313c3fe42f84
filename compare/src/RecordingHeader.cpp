#include "vesica/compare/RecordingHeader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <regex>

namespace vesica::compare {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// "sex: f", "gender = male"; else the words of free text. Both sexes named: unknown.
Sex sex_of(const std::string& text) {
  std::smatch m;
  if (std::regex_search(text, m, std::regex(R"((?:sex|gender)\s*[:=]\s*([a-z]+))")))
    return sex_from_word(m[1]);
  const bool female = std::regex_search(text, std::regex(R"(\b(female|woman|women)\b)"));
  const bool male = std::regex_search(text, std::regex(R"(\b(male|man|men)\b)"));
  if (female == male) return Sex::unknown;
  return female ? Sex::female : Sex::male;
}

std::optional<double> age_of(const std::string& text) {
  std::smatch m;
  if (std::regex_search(text, m, std::regex(R"(\bage\s*[:=]?\s*(\d{1,3})\b)")) ||
      std::regex_search(text, m, std::regex(R"(\b(\d{1,3})\s*-?\s*(?:years?|yrs?|y)\b)")))
    return std::stod(m[1]);
  return std::nullopt;
}

std::optional<double> fill_rate_of(const std::string& text) {
  std::smatch m;
  if (std::regex_search(text, m, std::regex(R"((\d+(?:\.\d+)?)\s*ml\s*/\s*min)")))
    return std::stod(m[1]);
  return std::nullopt;
}

}  // namespace

RecordingHeader parse_recording_header(const std::vector<std::string>& lines) {
  RecordingHeader h;
  for (const std::string& raw : lines) {
    const std::string line = lower(raw);
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
