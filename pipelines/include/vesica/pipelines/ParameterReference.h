#pragma once
// The parameter reference of the stage tools, made from their parameter tables:
// docs/parameters.md is exactly parameter_reference_markdown() (a test compares them),
// and `vesica parameters` prints it, so the docs cannot drift from the code's defaults.
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace vesica::pipelines {

// Every tool with a table, in pipeline order; or only `tool` when it is given.
std::string parameter_reference_markdown(const std::string& tool = "");

// {"tools": [ParameterTable::describe()...], "tools_without_tables": [...]}
nlohmann::json parameter_reference_json(const std::string& tool = "");

}  // namespace vesica::pipelines
