#pragma once
// Where the runner finds a stage tool's parameter table. The tables are linked in (each
// stage's small vesica_<tool>_parameters library, which depends only on core), not asked
// from the executables at run time: `vesica validate` then checks with exactly the code
// the tool parses its options with, costs no process start per tool, and works before the
// stages are built. Adding a tool is one name in VESICA_STAGE_TABLES
// (pipelines/CMakeLists.txt).
#include <optional>
#include <string>
#include <vector>

#include "vesica/core/ParameterTable.h"

namespace vesica::pipelines {

// The tool's table bound to default settings of its own (a fresh one on each call), or
// nothing when the tool has none: its params are then passed on unchecked.
std::optional<ParameterTable> stage_table(const std::string& tool);

// Tools with a table, in name order.
std::vector<std::string> tools_with_tables();

// Tools vesica ships that have no parameter table yet.
const std::vector<std::string>& tools_without_tables();

}  // namespace vesica::pipelines
