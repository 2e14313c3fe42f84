#pragma once
// vesica-surface's parameter table: every option of the command line and every `params`
// key of a surface stage in a pipeline file, with unit, range, help and the default of the
// library struct it is bound to (SurfaceSettings.h). Its library depends only on core, and
// this header names no settings type, so the runner links and includes it to check
// pipeline files before any stage runs.
#include "vesica/core/ParameterTable.h"

namespace vesica::surface {

struct SurfaceSettings;

ParameterTable parameter_table(SurfaceSettings& settings);
// Bound to default settings of its own (the runner's copy).
ParameterTable parameter_table();

}  // namespace vesica::surface
