#include "vesica/core/NumberRange.h"

#include <cmath>

#include <fmt/format.h>

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
  std::string text;
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
  if (!why_.empty()) j["why"] = why_;
  return j;
}

std::string format_number(double value) {
  return fmt::format("{}", value);
}

}  // namespace vesica
