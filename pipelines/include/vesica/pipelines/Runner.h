#pragma once
// Runs the stale stages of a plan in dependency order, up to N at a time. A failing stage
// stops further launches; what finished stays (stages write atomically), and because the
// failed stage's manifest was removed before it started, the next run resumes there.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/Staleness.h"

namespace vesica::pipelines {

struct RunOptions {
  std::vector<std::string> only;  // run only these stages (ids or stage names), if stale
  std::vector<std::string> from;  // rerun these and everything downstream, stale or not
  bool force = false;             // run every selected stage, stale or not
  int jobs = 1;
  // After a failure, keep starting the stages that do not depend on it (a study's other
  // variants); the run still ends failed.
  bool keep_going = false;
  bool capture = false;  // keep stage output in the result instead of passing it through
  // Where progress and passed-through stage output go (stderr in the CLI); may be empty.
  std::function<void(const std::string&)> progress;
};

struct StageOutcome {
  std::string id;
  std::string action;  // ran | failed | fresh | skipped | blocked
  std::string reason;  // why it ran (or why it is stale, when skipped/blocked)
  double seconds = 0;
  int exit_code = 0;
  std::vector<std::string> log;  // captured output lines (capture mode, or the failure)
  std::string last_line;         // last non-empty line the stage printed
};

struct RunResult {
  bool ok = true;
  std::string failed_stage;
  std::string failure_line;  // last non-empty line the failed stage printed
  std::vector<StageOutcome> stages;
  std::vector<std::string> ran() const;
  nlohmann::json to_json() const;
};

// Throws vesica::Error (usage) for an --only/--from name that matches no stage.
RunResult run_plan(const Plan& plan, const RunOptions& options);

// Which stages a run would start, with their reasons (shared by `run` and dry checks).
std::vector<bool> select_stages(const Plan& plan, const std::vector<StageStatus>& status,
                                const RunOptions& options);

}  // namespace vesica::pipelines
