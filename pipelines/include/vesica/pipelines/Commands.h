#pragma once
// The `vesica` command line: validate, run, status, export, phantom, help, --version.
namespace vesica::pipelines {

// Returns the process exit code: 0 success, 1 a stage failed, 2 usage or pipeline-file error.
int vesica_main(int argc, char** argv);

}  // namespace vesica::pipelines
