#pragma once
// A stage's parameter table (deal.II-style): every parameter of the stage with its pipeline
// key, unit, default, accepted values and help, each bound to a field of the stage's
// settings struct. From it come the command-line options and their checks
// (ParameterCli.h), the manifest's effective parameters (values()), the machine-readable
// description (`--parameters-json`, the runner's `vesica validate`, docs/parameters.md).
//
// A stage declares its table in one function, `ParameterTable parameter_table(Settings&)`,
// used by its main (bound to the settings it runs with), and `parameter_table()` for the
// runner (bound to a default-constructed copy: table_with_defaults()).
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/core/NumberRange.h"
#include "vesica/core/Parameter.h"
#include "vesica/core/ParameterText.h"

namespace vesica {

class ParameterTable {
 public:
  explicit ParameterTable(std::string tool);  // the stage tool: "surface" (vesica-surface)
  ParameterTable(ParameterTable&&) = default;
  ParameterTable& operator=(ParameterTable&&) = default;
  ParameterTable(const ParameterTable&) = delete;  // entries are bound to one settings struct
  ParameterTable& operator=(const ParameterTable&) = delete;

  Parameter& number(const std::string& name, double& field, const std::string& unit,
                    const NumberRange& range, const std::string& help);
  // A number in `range`, or the range's word ("auto"), which the field holds as
  // `word_value` (a value the range excludes, so that the two never mix).
  Parameter& number_or_word(const std::string& name, double& field, double word_value,
                            const std::string& unit, const NumberRange& range,
                            const std::string& help);
  template <class Int>
  Parameter& integer(const std::string& name, Int& field, const std::string& unit,
                     const NumberRange& range, const std::string& help);
  // Given: the field becomes true.
  Parameter& flag(const std::string& name, bool& field, const std::string& help);
  // Given: the field becomes false (the "no_..." switches of a setting that is on).
  Parameter& flag_off(const std::string& name, bool& field, const std::string& help);
  // One of `choices`; the field's default may be "" (none chosen).
  Parameter& choice(const std::string& name, std::string& field,
                    const std::vector<std::string>& choices, const std::string& help);
  template <class Enum>
  Parameter& choice(const std::string& name, Enum& field,
                    const std::vector<std::pair<std::string, Enum>>& names,
                    const std::string& help);
  // Free text stored as given (checked by the stage).
  Parameter& text(const std::string& name, std::string& field, const std::string& syntax,
                  const std::string& help);
  // Text in a form of the stage's own (points, lists, region=value): `assign` parses and
  // checks it into the settings (throwing ParameterValueError), `value` reads it back.
  Parameter& custom(const std::string& name, const std::string& unit, const std::string& syntax,
                    const std::string& help, std::function<void(const std::string&)> assign,
                    std::function<nlohmann::json()> value);
  // A named input file (`--measured F`): a command-line option, not a parameter.
  Parameter& input(const std::string& name, std::string& path, const std::string& help);
  // Free text naming a file the stage writes besides its output (Parameter::names_output).
  Parameter& output_file(const std::string& name, std::string& path, const std::string& syntax,
                         const std::string& help);

  // A file the stage always writes beside its output, named from the output's path by
  // `rule` ("" when none for that output): declared here so that the runner backs it up
  // and checks it like the output itself. `description` says it in words for the docs.
  using SideOutputRule = std::function<std::string(const std::string& output)>;
  void beside_output(const std::string& description, SideOutputRule rule);
  // The side outputs of `output`, by every rule.
  std::vector<std::string> side_outputs(const std::string& output) const;

  const std::string& tool() const { return tool_; }
  const std::deque<Parameter>& entries() const { return entries_; }
  std::deque<Parameter>& entries() { return entries_; }
  const Parameter* find(const std::string& name) const;
  // Names of the entries of these kinds (all kinds when empty).
  std::vector<std::string> names(const std::vector<Parameter::Kind>& kinds = {}) const;

  // Every parameter's effective value by name (inputs excluded): the manifest's parameters.
  nlohmann::json values() const;
  // {"tool", "parameters": [Parameter::describe()...], "inputs": [...], "side_outputs":
  // [descriptions]}
  nlohmann::json describe() const;

  // Keeps the settings the entries are bound to alive as long as the table.
  void keep_alive(std::shared_ptr<const void> owner) { owner_ = std::move(owner); }

 private:
  static Parameter entry(const std::string& name, Parameter::Kind kind, const std::string& unit,
                         const std::string& help);
  template <class Field, class Parse>
  Parameter& numeric(const std::string& name, Parameter::Kind kind, Field& field,
                     const std::string& unit, const NumberRange& range, const std::string& help,
                     Parse parse);
  Parameter& add(Parameter parameter);

  std::string tool_;
  std::vector<std::pair<std::string, SideOutputRule>> side_outputs_;  // description, rule
  std::deque<Parameter> entries_;  // a deque: entries keep their address while it grows
  std::shared_ptr<const void> owner_;
};

// The table bound to a default-constructed Settings of its own: its defaults are the
// library's, and assigning to it (the runner checking a pipeline file) touches nothing else.
template <class Settings>
ParameterTable table_with_defaults(ParameterTable (*build)(Settings&)) {
  auto settings = std::make_shared<Settings>();
  ParameterTable table = build(*settings);
  table.keep_alive(settings);
  return table;
}

// "0.001 is outside 0 (auto) or [1, 50] mm: <why>" — the ParameterValueError of a value
// outside its range.
[[noreturn]] void throw_out_of_range(const std::string& text, const NumberRange& range,
                                     const std::string& unit);

template <class Int>
Parameter& ParameterTable::integer(const std::string& name, Int& field, const std::string& unit,
                                   const NumberRange& range, const std::string& help) {
  return numeric(name, Parameter::Kind::Integer, field, unit, range, help, integer_from_text);
}

template <class Field, class Parse>
Parameter& ParameterTable::numeric(const std::string& name, Parameter::Kind kind, Field& field,
                                   const std::string& unit, const NumberRange& range,
                                   const std::string& help, Parse parse) {
  Parameter p = entry(name, kind, unit, help);
  p.range = range;
  p.assign = [&field, range, unit, parse](const std::string& text) {
    const auto v = parse(text);
    if (!range.contains(static_cast<double>(v))) throw_out_of_range(text, range, unit);
    field = static_cast<Field>(v);
  };
  p.value = [&field] { return nlohmann::json(field); };
  return add(std::move(p));
}

template <class Enum>
Parameter& ParameterTable::choice(const std::string& name, Enum& field,
                                  const std::vector<std::pair<std::string, Enum>>& names,
                                  const std::string& help) {
  Parameter p = entry(name, Parameter::Kind::Choice, "", help);
  for (const auto& n : names) p.choices.push_back(n.first);
  p.assign = [&field, names](const std::string& text) {
    std::string known;
    for (const auto& n : names) {
      if (n.first == text) {
        field = n.second;
        return;
      }
      known += (known.empty() ? "" : ", ") + n.first;
    }
    throw ParameterValueError("'" + text + "' is not one of " + known);
  };
  p.value = [&field, names] {
    for (const auto& n : names)
      if (n.second == field) return nlohmann::json(n.first);
    return nlohmann::json();
  };
  return add(std::move(p));
}

}  // namespace vesica
