#pragma once
// `vesica export --snakemake`: the same plan as a Snakemake workflow. Each rule calls the
// same executable with the same arguments in the same workdir, so the manifests it leaves
// are the ones `vesica run` would write, and either tool can continue the other's work.
#include <string>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

// Outputs without an extension ("phantom/dicom", "sim", "report") are folders, declared
// with directory(); an input inside another stage's folder depends on that folder.
std::string snakemake_workflow(const Plan& plan);

}  // namespace vesica::pipelines
