#pragma once
// A parameter table as command-line options: `--edge-mm NUMBER` for the entry edge_mm,
// bare flags for flags, each with a help line that shows what it accepts and its default,
// and a check of every given value (finite, in range, one of the choices) that refuses a
// bad one with a usage error naming the option, the value and what is accepted (exit 2).
// A hidden `--parameters-json` prints the table's description and exits 0.
#include <string>

#include "vesica/core/ParameterTable.h"

// CLI11's App by reference only: the executables that build one include <CLI/CLI.hpp>
// themselves, and the libraries including this header do not parse CLI11.
namespace CLI {
class App;
}  // namespace CLI

namespace vesica {

// The help group of the options that name a file the stage writes (Parameter::
// names_output): run_stage_main never takes their values for inputs to protect.
inline constexpr const char* kOutputOptionGroup = "Outputs";

// The table must outlive the parse: options store into the fields it is bound to.
void add_parameter_options(CLI::App& app, ParameterTable& table);

// "edge length (accepts [0.5, 50] mm; default 4 mm)": one help line.
std::string help_line(const Parameter& parameter);

}  // namespace vesica
