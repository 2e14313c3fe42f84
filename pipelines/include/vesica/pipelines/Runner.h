#pragma once
// Runs the stages of a plan that need it in dependency order, up to N at a time. A failing
// stage stops further launches; what finished stays (stages write atomically), and because
// the failed stage's manifest was removed before it started, the next run resumes there.
// Outputs someone edited are kept (Staleness.h): their stage does not run unless asked to
// discard the edit, and anything that replaces a file vesica did not leave there saves it
// first (EditBackup.h). SIGINT, SIGTERM and SIGHUP are passed on to the running stages,
// which the runner then waits for (SignalRelay.h).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/Staleness.h"

namespace vesica::pipelines {

struct RunOptions {
  std::vector<std::string> only;  // run only these stages (ids or stage names), if stale
  std::vector<std::string> from;  // rerun these and everything downstream, stale or not
  bool force = false;             // run every selected stage, stale or not
  // Run these stages even though their outputs were edited: the edits are saved under
  // .vesica/backup/ and replaced (`vesica reset`).
  std::vector<std::string> discard_edits;
  int jobs = 1;
  // After a failure, keep starting the stages that do not depend on it (a study's other
  // variants); the run still ends failed.
  bool keep_going = false;
  bool capture = false;  // keep stage output in the result instead of passing it through
  // Where progress and passed-through stage output go (stderr in the CLI); may be empty.
  std::function<void(const std::string&)> progress;
  // A running stage's own progress line, redrawn in place ("[mesh] tetrahedra 40% ...");
  // may be empty (then progress lines are dropped).
  std::function<void(const std::string&)> progress_line;
};

struct StageOutcome {
  std::string id;
  std::string action;  // ran | failed | interrupted | fresh | kept | skipped | blocked
  std::string reason;  // why it ran (or why it is stale, when skipped/blocked)
  double seconds = 0;
  int exit_code = 0;
  std::vector<std::string> log;        // captured output lines (capture mode, or the failure)
  std::string last_line;               // the stage's error line, or its last non-empty line
  std::vector<std::string> kept;       // kept: the edited outputs left as they are
  std::vector<std::string> backed_up;  // outputs saved before the stage replaced them
  std::string backup_folder;           // where (workdir-relative)
};

struct RunResult {
  bool ok = true;
  std::string failed_stage;
  std::string failure_line;  // the failed stage's error line
  int interrupted_by = 0;    // the signal that stopped the run, or 0
  std::vector<StageOutcome> stages;
  std::vector<std::string> ran() const;
  // The edited outputs kept, as "file (stage)", in plan order.
  std::vector<std::string> kept_files() const;
  nlohmann::json to_json() const;
};

// Throws vesica::Error (usage) for an --only/--from/--discard-edits name that matches no
// stage.
RunResult run_plan(const Plan& plan, const RunOptions& options);

// Which stages a run would start (shared by `run` and dry checks).
std::vector<bool> select_stages(const Plan& plan, const std::vector<StageStatus>& status,
                                const RunOptions& options);

}  // namespace vesica::pipelines
