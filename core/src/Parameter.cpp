#include "vesica/core/Parameter.h"

#include <algorithm>

namespace vesica {
namespace {

std::string joined(const std::vector<std::string>& items, const std::string& separator) {
  std::string text;
  for (const auto& item : items) text += (text.empty() ? "" : separator) + item;
  return text;
}

std::string shown(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number()) return format_number(value.get<double>());
  if (value.is_null()) return "none";
  if (value.is_array()) {
    std::string text;
    for (const auto& item : value) text += (text.empty() ? "" : ",") + shown(item);
    return text.empty() ? "none" : text;
  }
  if (value.is_object()) {  // "fixed=4,outlet=5"
    std::string text;
    for (const auto& [key, item] : value.items())
      text += (text.empty() ? "" : ",") + key + "=" + shown(item);
    return text.empty() ? "none" : text;
  }
  return value.dump();
}

}  // namespace

std::string Parameter::option() const {
  std::string dashed = name;
  std::replace(dashed.begin(), dashed.end(), '_', '-');
  return "--" + dashed;
}

std::string Parameter::accepted() const {
  switch (kind) {
    case Kind::Number:
    case Kind::Integer:
      return range.describe(unit);
    case Kind::Flag:
      return "on or off";
    case Kind::Choice:
      return "one of " + joined(choices, ", ");
    case Kind::Text:
      return syntax;
    case Kind::Input:
      return "a file";
  }
  return {};
}

std::string Parameter::default_text() const {
  if (kind == Kind::Flag) return default_value.get<bool>() ? "on" : "off";
  std::string text = shown(default_value);
  if (text.empty()) return "none";
  const bool numeric = kind == Kind::Number || kind == Kind::Integer;
  // A special value's or a word's meaning is in accepted(); a unit would mislead ("0 mm",
  // "auto mm" for auto).
  if (numeric && !default_value.is_number()) return text;
  if (numeric && !range.meaning_of(default_value.get<double>()).empty()) return text;
  return numeric && !unit.empty() && unit != "-" ? text + " " + unit : text;
}

nlohmann::json Parameter::describe() const {
  nlohmann::json j = {{"name", name}, {"option", option()},       {"kind", kind_name(kind)},
                      {"unit", unit}, {"default", default_value}, {"accepted", accepted()},
                      {"help", help}};
  if (kind == Kind::Number || kind == Kind::Integer) j["range"] = range.to_json();
  if (kind == Kind::Choice) j["choices"] = choices;
  if (kind == Kind::Text) j["syntax"] = syntax;
  if (names_output) j["writes_file"] = true;
  return j;
}

const char* kind_name(Parameter::Kind kind) {
  switch (kind) {
    case Parameter::Kind::Number:
      return "number";
    case Parameter::Kind::Integer:
      return "integer";
    case Parameter::Kind::Flag:
      return "flag";
    case Parameter::Kind::Choice:
      return "choice";
    case Parameter::Kind::Text:
      return "text";
    case Parameter::Kind::Input:
      return "input";
  }
  return "";
}

}  // namespace vesica
