#pragma once
// vesica-compare's parameter table: every option of the command line and every `params`
// key of a compare stage in a pipeline file (and its named inputs), with unit, range,
// help and the default of CompareOptions; the model a calibration starts from has
// vesica-simulate's entries (SimulateParameters.h). Depends only on core and simulate's
// parameter library (and header-only settings), so the runner links it to check pipeline
// files before any stage runs.
#include "vesica/compare/CompareRun.h"
#include "vesica/core/ParameterTable.h"

namespace vesica::compare {

ParameterTable parameter_table(CompareOptions& options);
// Bound to default settings of its own (the runner's copy).
ParameterTable parameter_table();

}  // namespace vesica::compare
