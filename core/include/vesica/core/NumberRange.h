#pragma once
// The values a numeric parameter accepts: an interval whose ends are each open or closed,
// plus a few special values outside it that mean something ("0 = none") or a word instead
// of a number ("auto"), and the reason a bound sits where it does. Every bound is finite in
// practice: a parameter table's ranges keep values physical and the work they cause (elements,
// frames, iterations) bounded.
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace vesica {

class NumberRange {
 public:
  // Start an interval: [lo, ...) or (lo, ...).
  static NumberRange at_least(double lo);
  static NumberRange greater_than(double lo);
  // Close it: [..., hi] or [..., hi).
  NumberRange& at_most(double hi);
  NumberRange& below(double hi);
  // A value outside the interval that is allowed and what it means ("auto", "none").
  NumberRange& or_value(double value, std::string meaning);
  // A word accepted instead of a number ("auto") and what it means; see
  // ParameterTable::number_or_word, which stores it.
  NumberRange& or_word(std::string word, std::string meaning);
  const std::string& word() const { return word_; }
  // Why the bounds are there, shown when a value is refused.
  NumberRange& because(std::string why);

  bool contains(double value) const;
  // The meaning of a special value ("auto"), or "" when `value` is not one.
  std::string meaning_of(double value) const;
  // "[0.5, 50] mm", "0 (none) or (0, 1000] kPa", "auto (1000 mu) or [0.1, 1000000] kPa".
  std::string describe(const std::string& unit) const;
  const std::string& why() const { return why_; }
  nlohmann::json to_json() const;

 private:
  double lo_ = -std::numeric_limits<double>::infinity();
  double hi_ = std::numeric_limits<double>::infinity();
  bool lo_open_ = true, hi_open_ = true;
  std::vector<std::pair<double, std::string>> special_;
  std::string word_, word_meaning_;
  std::string why_;
};

// Shortest text that reads back as the same number: 3, 0.05, 1000000, 1e+30.
std::string format_number(double value);

}  // namespace vesica
