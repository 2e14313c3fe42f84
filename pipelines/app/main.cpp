// `vesica`: runs pipeline files (see docs/pipeline-file.md).
#include "vesica/pipelines/Commands.h"

int main(int argc, char** argv) {
  return vesica::pipelines::vesica_main(argc, argv);
}
