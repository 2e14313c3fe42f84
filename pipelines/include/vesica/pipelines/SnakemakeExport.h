#pragma once
// `vesica export --snakemake`: the same plan as a Snakemake workflow. Each rule calls the
// same executable with the same arguments in the same workdir, so the manifests it leaves
// are the ones `vesica run` would write, and either tool can continue the other's work.
#include <string>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

// Outputs without an extension ("phantom/dicom", "sim", "report") are folders. They are
// not declared as directory() outputs, because Snakemake would add a marker file to them
// and change their content hash; a rule reading from a folder depends on the manifest of
// the stage that writes it instead (the manifest is written last, after the folder).
std::string snakemake_workflow(const Plan& plan);

}  // namespace vesica::pipelines
