// `vesica`: runs pipeline files (see docs/pipeline-file.md).
#include "vesica/core/StageSafety.h"
#include "vesica/pipelines/Commands.h"

int main(int argc, char** argv) {
  // study.csv and study.html are written like any output: a file-size limit is an error.
  vesica::ignore_file_size_signal();
  return vesica::pipelines::vesica_main(argc, argv);
}
