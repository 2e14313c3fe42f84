#include "vesica/pipelines/StageCheckpoint.h"

#include <sstream>

#include "vesica/core/ContentHash.h"
#include "vesica/simulate/protocol/CheckpointFile.h"

namespace vesica::pipelines {
namespace {

// The stage's arguments as the checkpoint records them: without --resume.
nlohmann::json arguments_of(const PlannedStage& s) {
  return without_resume(s.argv);
}

bool inputs_unchanged(const Plan& plan, const nlohmann::json& inputs) {
  if (!inputs.is_array() || inputs.empty()) return false;
  for (const auto& input : inputs) {
    const std::string path = input.value("path", ""), hash = input.value("hash", "");
    if (path.empty() || content_hash(plan.in_workdir(path)) != hash) return false;
  }
  return true;
}

}  // namespace

std::vector<std::string> without_resume(const std::vector<std::string>& argv) {
  std::vector<std::string> a;
  for (const auto& arg : argv)
    if (arg != "--resume") a.push_back(arg);
  return a;
}

bool stage_can_resume(const PlannedStage& s) {
  return s.tool == "simulate";
}

std::optional<StageCheckpoint> resumable_checkpoint(const Plan& plan, const PlannedStage& s) {
  if (!stage_can_resume(s)) return std::nullopt;
  const auto file = simulate::checkpoint_path_for_manifest(plan.in_workdir(s.manifest));
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  try {
    const simulate::CheckpointFile c = simulate::read_checkpoint(file);
    const nlohmann::json run = c.identity.value("run", nlohmann::json::object());
    if (run.value("arguments", nlohmann::json()) != arguments_of(s)) return std::nullopt;
    if (!inputs_unchanged(plan, run.value("inputs", nlohmann::json()))) return std::nullopt;
    return StageCheckpoint{file, c.identity.value("time_s", 0.0)};
  } catch (const std::exception&) {
    return std::nullopt;  // corrupt, foreign or unreadable: the stage runs from the start
  }
}

std::string checkpoint_status(const StageCheckpoint& c) {
  std::ostringstream s;
  s.precision(6);
  s << "interrupted (checkpoint at t = " << c.time_s << " s)";
  return s.str();
}

}  // namespace vesica::pipelines
