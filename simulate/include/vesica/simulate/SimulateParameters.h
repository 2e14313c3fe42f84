#pragma once
// vesica-simulate's parameter table: every option of the command line and every `params`
// key of a simulate stage in a pipeline file, with unit, range, help and the default of the
// library structs it is bound to (SimulateSettings.h). Its library depends only on core, and
// this header names no settings type, so the runner links and includes it to check
// pipeline files before any stage runs.
#include "vesica/core/ParameterTable.h"

namespace vesica::simulate {

struct SimulateSettings;

ParameterTable parameter_table(SimulateSettings& settings);
// Bound to default settings of its own (the runner's copy).
ParameterTable parameter_table();

}  // namespace vesica::simulate
