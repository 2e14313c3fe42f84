#pragma once
// What each stage of a plan asks a cluster's scheduler for: threads, memory and wall-clock
// time, from the stage's parameters and the size of the mesh it works on. `vesica export
// --snakemake` writes them as a rule's `threads:` and `resources: mem_mb=, runtime=`, which
// Snakemake's --slurm turns into --cpus-per-task, --mem and --time.
//
// The figures are upper estimates, not predictions: the cost models (StageResources.cpp)
// follow the measured growth of each stage with its size, with room for a slower or busier
// node and for the model's error, because a job that outgrows its request is killed while
// one that asks for too much only waits longer in the queue.
#include <cstddef>
#include <string>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

// The wall a stage works on: membrane triangles and urine tetrahedra (0 without --fluid).
struct MeshSize {
  double triangles = 0.0;
  double tetrahedra = 0.0;
  std::string basis;  // "1,710 triangles (mesh.json)" or how it was estimated
};

struct StageResources {
  bool known = false;  // false: a tool vesica does not ship; the workflow's defaults apply
  int threads = 1;
  long mem_mb = 0;       // peak resident memory asked for (MB)
  long runtime_min = 0;  // wall-clock limit asked for (minutes)
  std::string basis;     // what the estimate rests on, one line for the Snakefile
};

// The wall stage `index` works on: the mesh report of the nearest upstream mesh stage when
// it exists, else estimated from the upstream surface's edge length (or target triangle
// count) and its volume (the shape's, the phantom's bladder, or an adult bladder's).
MeshSize mesh_size_for(const Plan& plan, std::size_t index);

StageResources stage_resources(const Plan& plan, std::size_t index);

}  // namespace vesica::pipelines
