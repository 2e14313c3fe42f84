#include "vesica/core/ParameterTable.h"

#include <algorithm>
#include <stdexcept>

namespace vesica {

ParameterTable::ParameterTable(std::string tool) : tool_(std::move(tool)) {}

void throw_out_of_range(const std::string& text, const NumberRange& range,
                        const std::string& unit) {
  std::string message = text + " is outside " + range.describe(unit);
  if (!range.why().empty()) message += ": " + range.why();
  throw ParameterValueError(message);
}

Parameter& ParameterTable::add(Parameter parameter) {
  if (find(parameter.name))  // a programming error in a stage's table, caught by its tests
    throw std::logic_error("parameter table of " + tool_ + ": '" + parameter.name + "' twice");
  parameter.default_value = parameter.value();
  entries_.push_back(std::move(parameter));
  return entries_.back();
}

Parameter& ParameterTable::number(const std::string& name, double& field, const std::string& unit,
                                  const NumberRange& range, const std::string& help) {
  Parameter p;
  p.name = name;
  p.kind = Parameter::Kind::Number;
  p.unit = unit;
  p.range = range;
  p.help = help;
  p.assign = [&field, range, unit](const std::string& text) {
    const double v = number_from_text(text);
    if (!range.contains(v)) throw_out_of_range(text, range, unit);
    field = v;
  };
  p.value = [&field] { return nlohmann::json(field); };
  return add(std::move(p));
}

namespace {

Parameter flag_entry(const std::string& name, bool& field, bool when_given,
                     const std::string& help) {
  Parameter p;
  p.name = name;
  p.kind = Parameter::Kind::Flag;
  p.help = help;
  // "true" is what the runner passes for `name: true` (and CLI11 for a bare flag).
  p.assign = [&field, when_given](const std::string& text) {
    if (text == "true")
      field = when_given;
    else if (text == "false")
      field = !when_given;
    else
      throw ParameterValueError("'" + text + "' is not true or false");
  };
  p.value = [&field, when_given] { return nlohmann::json(field == when_given); };
  return p;
}

}  // namespace

Parameter& ParameterTable::flag(const std::string& name, bool& field, const std::string& help) {
  return add(flag_entry(name, field, true, help));
}

Parameter& ParameterTable::flag_off(const std::string& name, bool& field, const std::string& help) {
  return add(flag_entry(name, field, false, help));
}

Parameter& ParameterTable::choice(const std::string& name, std::string& field,
                                  const std::vector<std::string>& choices,
                                  const std::string& help) {
  std::vector<std::pair<std::string, std::string>> names;
  for (const auto& c : choices) names.emplace_back(c, c);
  return choice<std::string>(name, field, names, help);
}

Parameter& ParameterTable::text(const std::string& name, std::string& field,
                                const std::string& syntax, const std::string& help) {
  return custom(
      name, "", syntax, help, [&field](const std::string& text) { field = text; },
      [&field] { return nlohmann::json(field); });
}

Parameter& ParameterTable::custom(const std::string& name, const std::string& unit,
                                  const std::string& syntax, const std::string& help,
                                  std::function<void(const std::string&)> assign,
                                  std::function<nlohmann::json()> value) {
  Parameter p;
  p.name = name;
  p.kind = Parameter::Kind::Text;
  p.unit = unit;
  p.syntax = syntax;
  p.help = help;
  p.assign = std::move(assign);
  p.value = std::move(value);
  return add(std::move(p));
}

Parameter& ParameterTable::input(const std::string& name, std::string& path,
                                 const std::string& help) {
  Parameter& p = text(name, path, "file", help);
  p.kind = Parameter::Kind::Input;
  return p;
}

const Parameter* ParameterTable::find(const std::string& name) const {
  for (const auto& p : entries_)
    if (p.name == name) return &p;
  return nullptr;
}

std::vector<std::string> ParameterTable::names(const std::vector<Parameter::Kind>& kinds) const {
  std::vector<std::string> out;
  for (const auto& p : entries_)
    if (kinds.empty() || std::count(kinds.begin(), kinds.end(), p.kind) > 0) out.push_back(p.name);
  return out;
}

nlohmann::json ParameterTable::values() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& p : entries_)
    if (p.kind != Parameter::Kind::Input) j[p.name] = p.value();
  return j;
}

nlohmann::json ParameterTable::describe() const {
  nlohmann::json parameters = nlohmann::json::array(), inputs = nlohmann::json::array();
  for (const auto& p : entries_)
    (p.kind == Parameter::Kind::Input ? inputs : parameters).push_back(p.describe());
  return {{"tool", tool_}, {"parameters", parameters}, {"inputs", inputs}};
}

}  // namespace vesica
