#pragma once
// A pipeline file's parameters checked against the stage tools' parameter tables before
// anything runs: every stage's `params` and named `inputs`, and every value of its study
// (matrix axes and variants). An unknown key is reported at the key with a suggestion
// ("unknown parameter 'mu_kp' for simulate (did you mean 'mu_kpa'?)"), a value of the
// wrong kind or out of range at the value with what is accepted.
#include <string>
#include <vector>

#include "vesica/pipelines/Diagnostics.h"
#include "vesica/pipelines/PipelineFile.h"

namespace vesica::pipelines {

// Fills `diagnostics`; returns the tools whose params were not checked because they have
// no table (each once, in file order).
std::vector<std::string> check_parameters(const PipelineSpec& spec, Diagnostics& diagnostics);

}  // namespace vesica::pipelines
