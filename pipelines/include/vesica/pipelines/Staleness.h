#pragma once
// Decides which stages must run by comparing each stage's manifest (tool version, exact
// invocation, content hashes of inputs and outputs) with the plan and the files on disk.
// Hashes are only recomputed when a file's size or modification time changed, so that a
// pipeline whose stages are all fresh is checked without reading any large file.
#include <string>
#include <vector>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

enum class Freshness { Fresh, Stale, Missing };
const char* to_string(Freshness f);

struct StageStatus {
  Freshness state = Freshness::Missing;
  std::string reason;  // empty when fresh
};

// One entry per plan stage, in plan order. A stage is stale when its own manifest
// disagrees with the plan or the files, or when a stage it depends on is stale.
std::vector<StageStatus> assess(const Plan& plan);

// The stage's own reason to run, ignoring upstream stages ("" when it agrees).
StageStatus assess_stage(const Plan& plan, std::size_t index);

// "parameter edge_mm changed (4 -> 3)" style description of how two invocations differ.
std::string describe_invocation_change(const std::vector<std::string>& before,
                                       const std::vector<std::string>& after);

}  // namespace vesica::pipelines
