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

Parameter ParameterTable::entry(const std::string& name, Parameter::Kind kind,
                                const std::string& unit, const std::string& help) {
  Parameter p;
  p.name = name;
  p.kind = kind;
  p.unit = unit;
  p.help = help;
  return p;
}

Parameter& ParameterTable::number(const std::string& name, double& field, const std::string& unit,
                                  const NumberRange& range, const std::string& help) {
  return numeric(name, Parameter::Kind::Number, field, unit, range, help, number_from_text);
}

Parameter& ParameterTable::number_or_word(const std::string& name, double& field, double word_value,
                                          const std::string& unit, const NumberRange& range,
                                          const std::string& help) {
  Parameter& p = number(name, field, unit, range, help);
  p.assign = [&field, word_value, range, unit, number = p.assign](const std::string& text) {
    if (text == range.word())
      field = word_value;
    else
      number(text);
  };
  p.value = [&field, word_value, word = range.word()] {
    return field == word_value ? nlohmann::json(word) : nlohmann::json(field);
  };
  p.default_value = p.value();
  return p;
}

namespace {

// A flag that stores `when_given` when given.
void bind_flag(bool& field, bool when_given, Parameter& p) {
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
}

}  // namespace

Parameter& ParameterTable::flag(const std::string& name, bool& field, const std::string& help) {
  Parameter p = entry(name, Parameter::Kind::Flag, "", help);
  bind_flag(field, true, p);
  return add(std::move(p));
}

Parameter& ParameterTable::flag_off(const std::string& name, bool& field, const std::string& help) {
  Parameter p = entry(name, Parameter::Kind::Flag, "", help);
  bind_flag(field, false, p);
  return add(std::move(p));
}

Parameter& ParameterTable::choice(const std::string& name, std::string& field,
                                  const std::vector<std::string>& choices,
                                  const std::string& help) {
  std::vector<std::pair<std::string, std::string>> names;
  names.reserve(choices.size());
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
  Parameter p = entry(name, Parameter::Kind::Text, unit, help);
  p.syntax = syntax;
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

Parameter& ParameterTable::output_file(const std::string& name, std::string& path,
                                       const std::string& syntax, const std::string& help) {
  Parameter& p = text(name, path, syntax, help);
  p.names_output = true;
  return p;
}

void ParameterTable::beside_output(const std::string& description, SideOutputRule rule) {
  side_outputs_.emplace_back(description, std::move(rule));
}

std::vector<std::string> ParameterTable::side_outputs(const std::string& output) const {
  std::vector<std::string> out;
  for (const auto& [description, rule] : side_outputs_)
    if (std::string path = rule(output); !path.empty()) out.push_back(std::move(path));
  return out;
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
  nlohmann::json side = nlohmann::json::array();
  for (const auto& entry : side_outputs_) side.push_back(entry.first);
  return {{"tool", tool_}, {"parameters", parameters}, {"inputs", inputs}, {"side_outputs", side}};
}

}  // namespace vesica
