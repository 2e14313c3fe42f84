#include "vesica/pipelines/StageFailure.h"

#include <signal.h>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/JsonFile.h"
#include "vesica/core/UidScrub.h"
#include "vesica/pipelines/StageManifest.h"
#include "vesica/pipelines/StateFolder.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

constexpr std::size_t kMaxErrorLine = 300;

const char* state_name(StageFailure::State s) {
  switch (s) {
    case StageFailure::State::Running:
      return "running";
    case StageFailure::State::Interrupted:
      return "interrupted";
    case StageFailure::State::Failed:
      return "failed";
  }
  return "failed";
}

StageFailure::State state_from(const std::string& name) {
  if (name == "running") return StageFailure::State::Running;
  if (name == "interrupted") return StageFailure::State::Interrupted;
  return StageFailure::State::Failed;
}

}  // namespace

bool StageFailure::runner_alive() const {
  return state == State::Running && pid > 0 && ::kill(static_cast<pid_t>(pid), 0) == 0;
}

std::string StageFailure::describe() const {
  switch (state) {
    case State::Running:
      return runner_alive() ? "running (vesica PID " + std::to_string(pid) + ")"
                            : "interrupted: the run was killed";
    case State::Interrupted:
      return "interrupted: " + without_uids(error);
    case State::Failed:
      break;
  }
  return "failed (exit " + std::to_string(exit_code) + "): " + without_uids(error);
}

void write_stage_failure(const Plan& plan, const std::string& id, const StageFailure& failure) {
  nlohmann::json outputs = nlohmann::json::array();
  for (const auto& r : failure.outputs_before) outputs.push_back(to_json(r));
  const nlohmann::json j = {{"state", state_name(failure.state)},
                            {"pid", failure.pid},
                            {"exit_code", failure.exit_code},
                            {"error", without_uids(failure.error)},
                            {"utc", failure.utc.empty() ? utc_now_iso8601() : failure.utc},
                            {"outputs_before", outputs}};
  write_text_atomically(plan.in_workdir(state::failure_path(id)), j.dump(2) + "\n");
}

std::optional<StageFailure> read_stage_failure(const Plan& plan, const std::string& id) {
  const auto j = read_json_file(plan.in_workdir(state::failure_path(id)));
  if (!j || !j->is_object()) return std::nullopt;
  StageFailure f;
  try {
    f.state = state_from(j->value("state", ""));
    f.pid = j->value("pid", 0L);
    f.exit_code = j->value("exit_code", 0);
    f.error = j->value("error", "");
    f.utc = j->value("utc", "");
    for (const auto& r : j->value("outputs_before", nlohmann::json::array()))
      if (r.is_object()) {
        FileRecord record = file_record_from_json(r);
        if (stays_inside_workdir(record.path)) f.outputs_before.push_back(std::move(record));
      }
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // a field of the wrong type: not a record vesica wrote
  }
  return f;
}

void clear_stage_failure(const Plan& plan, const std::string& id) {
  std::error_code ec;
  fs::remove(plan.in_workdir(state::failure_path(id)), ec);
}

std::string error_line(const std::vector<std::string>& lines) {
  std::string line;
  for (const auto& l : lines)
    if (l.find("error:") != std::string::npos) {
      line = l;
      break;
    }
  if (line.empty())
    for (auto it = lines.rbegin(); it != lines.rend(); ++it)
      if (it->find_first_not_of(" \t\r") != std::string::npos) {
        line = *it;
        break;
      }
  if (line.size() > kMaxErrorLine) line = line.substr(0, kMaxErrorLine - 3) + "...";
  return line;
}

}  // namespace vesica::pipelines
