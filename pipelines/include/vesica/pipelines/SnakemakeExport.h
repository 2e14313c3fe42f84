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
//
// Edited outputs are kept as `vesica run` keeps them (Staleness.h): when Snakemake reads
// the workflow, it asks `vesica status` which stages keep an edit and leaves their rules
// out. Snakemake deletes a rule's outputs before running it, so this is the only way it
// can keep them; the rules that read an edited file then run because it is newer.
std::string snakemake_workflow(const Plan& plan);

}  // namespace vesica::pipelines
