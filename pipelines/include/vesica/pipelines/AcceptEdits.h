#pragma once
// `vesica accept STAGE`: the files now at a stage's outputs become its outputs, as if the
// stage had written them from its current inputs with its current command line. Its
// manifest is rewritten with their hashes and lists them under "accepted_edits" (path,
// hash, the hash the stage had written, time), so the stage is fresh again and a later
// rerun still saves them before replacing them (EditBackup.h). Works as well for a stage
// that failed or never ran, whose output someone made by hand.
#include <string>
#include <vector>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

// The outputs accepted (workdir-relative); empty when they already were the stage's own.
// Throws vesica::Error naming the file when an input or the main output is missing.
std::vector<std::string> accept_edits(const Plan& plan, std::size_t index);

}  // namespace vesica::pipelines
