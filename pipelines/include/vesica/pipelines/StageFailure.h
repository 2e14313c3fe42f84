#pragma once
// What the runner remembers of a stage that did not finish: .vesica/<id>.failed.json
// (StateFolder.h). It is written when the stage starts ("running", with the runner's PID),
// rewritten when it fails or is interrupted, and removed when it succeeds; so after a
// runner that was killed outright the stage still reads "interrupted". It also keeps the
// stage's output records from before the start (its manifest is removed then), so that
// the next run can tell the stage's own earlier outputs from a file someone edited since.
#include <optional>
#include <string>
#include <vector>

#include "vesica/core/StageRecord.h"
#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

struct StageFailure {
  enum class State { Running, Failed, Interrupted };
  State state = State::Failed;
  long pid = 0;       // of the runner that started the stage
  int exit_code = 0;  // Failed: the stage's exit code (128 + signal when killed)
  std::string error;  // the first line of the stage's error, or what interrupted it
  std::string utc;    // when it was written
  std::vector<FileRecord> outputs_before;

  // "failed (exit 1): vesica-mesh: error: ...", "interrupted: SIGINT", "running (vesica PID
  // 123)"; a "running" record whose runner is gone reads "interrupted: the run was killed".
  std::string describe() const;
  // Running and its runner process still exists.
  bool runner_alive() const;
};

void write_stage_failure(const Plan& plan, const std::string& id, const StageFailure& failure);
std::optional<StageFailure> read_stage_failure(const Plan& plan, const std::string& id);
void clear_stage_failure(const Plan& plan, const std::string& id);

// The line that says why a stage failed: its first line containing "error:", else its last
// non-empty line; at most 300 characters.
std::string error_line(const std::vector<std::string>& lines);

}  // namespace vesica::pipelines
