#pragma once
// A stage that declares it can resume (vesica-simulate: docs/simulate.md, "Checkpoint and
// resume") leaves a checkpoint when it is interrupted, beside the manifests
// (.vesica/checkpoints/<output>/checkpoint.bin). The runner reruns such a stage with
// --resume when the checkpoint is valid and was computed from the stage's present inputs
// and arguments, and `vesica status` says where it stands.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

struct StageCheckpoint {
  std::filesystem::path file;
  double time_s = 0.0;  // the simulated time it holds (s)
};

// Whether the stage's tool can continue from a checkpoint (--resume).
bool stage_can_resume(const PlannedStage& s);
// The stage's checkpoint when it is readable, intact and of the stage's present inputs
// (content hashes) and arguments; nullopt otherwise (never throws).
std::optional<StageCheckpoint> resumable_checkpoint(const Plan& plan, const PlannedStage& s);
// A stage's arguments without --resume, which the runner adds to continue an interrupted
// run: not a parameter (a resumed stage is as fresh as one run whole), never a reason to run.
std::vector<std::string> without_resume(const std::vector<std::string>& argv);

// "interrupted (checkpoint at t = 75 s)".
std::string checkpoint_status(const StageCheckpoint& c);

}  // namespace vesica::pipelines
