#include "vesica/compare/recording/RecordingHeader.h"

#include <cctype>
#include <cstdlib>

#include "vesica/core/Error.h"
#include "vesica/io/CsvTable.h"

namespace vesica::compare {
namespace {

// A header line as words, numbers and single symbols, lower case, spaces dropped: the
// patterns below are then a few comparisons per token, linear in the line's length (a
// backtracking regular expression over a 60,000-character line recursed per character).
struct Token {
  enum Kind { Word, Number, Symbol } kind;
  std::string text;
  bool glued = false;  // follows a letter or digit without a space (no word boundary)
};

std::vector<Token> tokens_of(const std::string& line) {
  std::vector<Token> out;
  const auto alpha = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  const auto digit = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; };
  for (std::size_t i = 0; i < line.size();) {
    const char c = line[i];
    const bool glued = i > 0 && (alpha(line[i - 1]) || digit(line[i - 1]));
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    Token t{alpha(c) ? Token::Word : digit(c) ? Token::Number : Token::Symbol, "", glued};
    const std::size_t start = i;
    if (t.kind == Token::Symbol)
      ++i;
    else
      while (i < line.size() && (t.kind == Token::Word ? alpha(line[i]) : digit(line[i]))) ++i;
    for (std::size_t k = start; k < i; ++k)
      t.text += static_cast<char>(std::tolower(static_cast<unsigned char>(line[k])));
    out.push_back(std::move(t));
  }
  return out;
}

bool is(const std::vector<Token>& t, std::size_t i, Token::Kind kind,
        const std::string& text = {}) {
  return i < t.size() && t[i].kind == kind && (text.empty() || t[i].text == text);
}

bool word_in(const std::vector<Token>& t, std::size_t i, std::initializer_list<const char*> words) {
  if (!is(t, i, Token::Word)) return false;
  for (const char* w : words)
    if (t[i].text == w) return true;
  return false;
}

// "sex: f", "gender = male"; else the words of free text. Both sexes named: unknown.
Sex sex_of(const std::vector<Token>& t) {
  for (std::size_t i = 0; i + 2 < t.size(); ++i)
    if (word_in(t, i, {"sex", "gender"}) &&
        (is(t, i + 1, Token::Symbol, ":") || is(t, i + 1, Token::Symbol, "=")) &&
        is(t, i + 2, Token::Word))
      return sex_from_word(t[i + 2].text);
  bool female = false, male = false;
  for (std::size_t i = 0; i < t.size(); ++i) {
    female = female || word_in(t, i, {"female", "woman", "women"});
    male = male || word_in(t, i, {"male", "man", "men"});
  }
  if (female == male) return Sex::unknown;
  return female ? Sex::female : Sex::male;
}

// A whole number of one to three digits standing alone at token i.
bool short_number(const std::vector<Token>& t, std::size_t i) {
  return is(t, i, Token::Number) && !t[i].glued && t[i].text.size() <= 3 &&
         !(i + 1 < t.size() && t[i + 1].glued && t[i + 1].kind == Token::Word);
}

// "age: 68", "age 68"; else "34 years", "68-year-old", "34 y".
std::optional<double> age_of(const std::vector<Token>& t) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!word_in(t, i, {"age"}) || t[i].glued) continue;
    std::size_t n = i + 1;
    if (is(t, n, Token::Symbol, ":") || is(t, n, Token::Symbol, "=")) ++n;
    if (short_number(t, n)) return std::atof(t[n].text.c_str());
  }
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!is(t, i, Token::Number) || t[i].glued || t[i].text.size() > 3) continue;
    std::size_t n = i + 1;
    if (is(t, n, Token::Symbol, "-")) ++n;
    if (word_in(t, n, {"years", "year", "yrs", "yr", "y"})) return std::atof(t[i].text.c_str());
  }
  return std::nullopt;
}

// "50 ml/min", "12.5ml / min".
std::optional<double> fill_rate_of(const std::vector<Token>& t) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!is(t, i, Token::Number)) continue;
    std::string number = t[i].text;
    std::size_t n = i + 1;
    if (is(t, n, Token::Symbol, ".") && is(t, n + 1, Token::Number) && t[n + 1].glued) {
      number += "." + t[n + 1].text;
      n += 2;
    }
    if (word_in(t, n, {"ml"}) && is(t, n + 1, Token::Symbol, "/") && is(t, n + 2, Token::Word) &&
        t[n + 2].text.rfind("min", 0) == 0)
      return std::atof(number.c_str());
  }
  return std::nullopt;
}

}  // namespace

RecordingHeader parse_recording_header(const std::vector<std::string>& lines) {
  RecordingHeader h;
  for (const std::string& line : lines) {
    const std::vector<Token> t = tokens_of(line);
    if (h.sex == Sex::unknown) h.sex = sex_of(t);
    if (!h.age_years) h.age_years = age_of(t);
    if (!h.stated_fill_rate_ml_min) h.stated_fill_rate_ml_min = fill_rate_of(t);
  }
  return h;
}

RecordingHeader read_recording_header(const std::filesystem::path& csv) {
  try {
    return parse_recording_header(io::read_leading_comments(csv));
  } catch (const Error&) {
    return {};  // the recording's reader says what is wrong with the file
  }
}

}  // namespace vesica::compare
