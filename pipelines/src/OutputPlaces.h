#pragma once
// Internal to vesica_pipelines: where a stage's output may not go. vesica deletes only
// what it made, so an output may not be or contain the workdir, the pipeline file, an
// external input or one of its own stage's inputs (`output: .` would replace the folder
// holding the pipeline and its data). Each such output is reported at its line.
#include "vesica/pipelines/Diagnostics.h"
#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines::detail {

void check_output_places(const Plan& plan, const PipelineSpec& spec, Diagnostics& diagnostics);

}  // namespace vesica::pipelines::detail
