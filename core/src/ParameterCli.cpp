#include "vesica/core/ParameterCli.h"

#include <iostream>

#include <CLI/CLI.hpp>

namespace vesica {
namespace {

std::string type_name(const Parameter& p) {
  switch (p.kind) {
    case Parameter::Kind::Number:
      return "NUMBER";
    case Parameter::Kind::Integer:
      return "INT";
    case Parameter::Kind::Choice: {
      std::string names;
      for (const auto& c : p.choices) names += (names.empty() ? "" : "|") + c;
      return names;
    }
    case Parameter::Kind::Input:
      return "FILE";
    default:
      return "TEXT";
  }
}

}  // namespace

std::string help_line(const Parameter& p) {
  if (p.kind == Parameter::Kind::Input) return p.help;
  if (p.kind == Parameter::Kind::Flag) return p.help + " (default " + p.default_text() + ")";
  return p.help + " (accepts " + p.accepted() + "; default " + p.default_text() + ")";
}

void add_parameter_options(CLI::App& app, ParameterTable& table) {
  for (Parameter& p : table.entries()) {
    // CLI11 reports a ValidationError as a usage error; its text names the option.
    auto store = [&p](const std::string& text) {
      try {
        p.assign(text);
      } catch (const ParameterValueError& e) {
        throw CLI::ValidationError(p.option() + " " + e.what());
      }
    };
    // "Outputs": a file the stage writes, which StageSafety.h never protects as an input.
    const std::string group = p.kind == Parameter::Kind::Input ? "Inputs"
                              : p.names_output                 ? kOutputOptionGroup
                                                               : "Parameters";
    if (p.kind == Parameter::Kind::Flag)
      app.add_flag_callback(
             p.option(), [store] { store("true"); }, help_line(p))
          ->group(group);
    else
      app.add_option_function<std::string>(p.option(), store, help_line(p))
          ->type_name(type_name(p))
          ->group(group);
  }
  app.add_flag_callback(
         "--parameters-json",
         [&table] {
           std::cout << table.describe().dump(2) << std::endl;
           throw CLI::Success();
         },
         "Print the parameter table as JSON and exit")
      ->group("");
}

}  // namespace vesica
