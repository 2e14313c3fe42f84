#include "vesica/core/NumberRange.h"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace vesica {

NumberRange NumberRange::at_least(double lo) {
  NumberRange r;
  r.lo_ = lo;
  r.lo_open_ = false;
  return r;
}

NumberRange NumberRange::greater_than(double lo) {
  NumberRange r;
  r.lo_ = lo;
  r.lo_open_ = true;
  return r;
}

NumberRange& NumberRange::at_most(double hi) {
  hi_ = hi;
  hi_open_ = false;
  return *this;
}

NumberRange& NumberRange::below(double hi) {
  hi_ = hi;
  hi_open_ = true;
  return *this;
}

NumberRange& NumberRange::or_value(double value, std::string meaning) {
  special_.emplace_back(value, std::move(meaning));
  return *this;
}

NumberRange& NumberRange::or_word(std::string word, std::string meaning) {
  word_ = std::move(word);
  word_meaning_ = std::move(meaning);
  return *this;
}

NumberRange& NumberRange::because(std::string why) {
  why_ = std::move(why);
  return *this;
}

bool NumberRange::contains(double value) const {
  if (!std::isfinite(value)) return false;
  for (const auto& s : special_)
    if (value == s.first) return true;
  const bool above_lo = lo_open_ ? value > lo_ : value >= lo_;
  const bool below_hi = hi_open_ ? value < hi_ : value <= hi_;
  return above_lo && below_hi;
}

std::string NumberRange::meaning_of(double value) const {
  for (const auto& s : special_)
    if (value == s.first) return s.second;
  return {};
}

std::string NumberRange::describe(const std::string& unit) const {
  std::string text = word_.empty() ? "" : word_ + " (" + word_meaning_ + ") or ";
  for (const auto& s : special_) text += format_number(s.first) + " (" + s.second + ") or ";
  const auto end = [](double v) { return std::isinf(v) ? std::string("inf") : format_number(v); };
  text += (lo_open_ ? "(" : "[") + end(lo_) + ", " + end(hi_) + (hi_open_ ? ")" : "]");
  if (!unit.empty() && unit != "-") text += " " + unit;
  return text;
}

nlohmann::json NumberRange::to_json() const {
  const auto end = [](double v) { return std::isinf(v) ? nlohmann::json() : nlohmann::json(v); };
  nlohmann::json j = {{"min", end(lo_)},
                      {"min_open", lo_open_},
                      {"max", end(hi_)},
                      {"max_open", hi_open_},
                      {"special", nlohmann::json::array()}};
  for (const auto& s : special_)
    j["special"].push_back({{"value", s.first}, {"meaning", s.second}});
  if (!word_.empty()) j["word"] = {{"word", word_}, {"meaning", word_meaning_}};
  if (!why_.empty()) j["why"] = why_;
  return j;
}

std::string format_number(double value) {
  // Whole numbers in full ("1000000", not "1e+06"), others in their shortest exact form.
  if (value == std::floor(value) && std::abs(value) < 1e15) return fmt::format("{:.0f}", value);
  return fmt::format("{}", value);
}

}  // namespace vesica
