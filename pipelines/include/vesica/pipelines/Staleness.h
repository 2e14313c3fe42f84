#pragma once
// Decides what each stage of a plan is by comparing its manifest (tool version, exact
// invocation, content hashes of inputs and outputs, StageManifest.h) with the plan and the
// files on disk:
//  - fresh: everything agrees;
//  - edited: an output differs from what the stage recorded: someone edited it (Slicer,
//    MeshLab, Gmsh). The edit is the user's and is kept: the stage is not rerun (until
//    `vesica reset`), and the stages that read the file see a changed input and rerun;
//  - stale: the version, the invocation or an input changed, an output is missing, or a
//    stage it depends on will run;
//  - missing: never run here; failed: its last run failed or was interrupted; running: a
//    `vesica` is running it now.
#include <string>
#include <vector>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

enum class Freshness { Fresh, Stale, Missing, Edited, Failed, Running };
const char* to_string(Freshness f);

struct StageStatus {
  Freshness state = Freshness::Missing;
  // Why (empty when fresh). Failed: "failed (exit 1): <the stage's error>".
  std::string reason;
  std::vector<std::string> edited;  // Edited: the outputs that differ (workdir-relative)

  // The stage would run in a plain `vesica run`.
  bool will_run() const;
  // One line for `vesica status`: "fresh", "stale: input x changed", "edited (kept):
  // bladder.ply", "failed (exit 1): ...".
  std::string line() const;
};

// One entry per plan stage, in plan order. A stage is stale when its own manifest
// disagrees with the plan or the files, or when a stage it depends on will run; a stage
// downstream of an edited one only when its own inputs changed.
std::vector<StageStatus> assess(const Plan& plan);

// The stage's own state, ignoring upstream stages.
StageStatus assess_stage(const Plan& plan, std::size_t index);

// "parameter edge_mm changed (4 -> 3)" style description of how two invocations differ.
std::string describe_invocation_change(const std::vector<std::string>& before,
                                       const std::vector<std::string>& after);

}  // namespace vesica::pipelines
