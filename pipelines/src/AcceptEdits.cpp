#include "vesica/pipelines/AcceptEdits.h"

#include <algorithm>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/pipelines/StageFailure.h"
#include "vesica/pipelines/StageManifest.h"
#include "vesica/pipelines/StateFolder.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

FileRecord record_at(const Plan& plan, const std::string& path) {
  FileRecord r = record_file(plan.in_workdir(path));
  r.path = path;
  return r;
}

std::vector<std::string> paths_of(const std::vector<FileRecord>& records) {
  std::vector<std::string> out;
  out.reserve(records.size());
  for (const auto& r : records) out.push_back(r.path);
  return out;
}

}  // namespace

std::vector<std::string> accept_edits(const Plan& plan, std::size_t index) {
  const PlannedStage& s = plan.stages[index];
  const auto old = read_stage_manifest(plan.in_workdir(s.manifest));
  const bool had = old && old->readable();
  nlohmann::json manifest = had ? old->json : nlohmann::json{{"tool", "vesica-" + s.tool}};

  nlohmann::json inputs = nlohmann::json::array();
  for (const auto& path : had ? paths_of(old->inputs) : s.inputs) {
    if (!fs::exists(plan.in_workdir(path)))
      fail(path, "input of " + s.id + " is missing", "run the stages before it first");
    inputs.push_back(to_json(record_at(plan, path)));
  }

  std::vector<std::string> places = had ? paths_of(old->outputs) : std::vector<std::string>{};
  if (std::find(places.begin(), places.end(), s.output) == places.end())
    places.insert(places.begin(), s.output);
  nlohmann::json outputs = nlohmann::json::array();
  nlohmann::json accepted = manifest.value("accepted_edits", nlohmann::json::array());
  std::vector<std::string> files;
  for (const auto& path : places) {
    if (!fs::exists(plan.in_workdir(path))) {
      if (path == s.output) fail(path, "does not exist: nothing to accept for " + s.id);
      continue;  // a report or sidecar the stage would write again
    }
    const FileRecord now = record_at(plan, path);
    outputs.push_back(to_json(now));
    const FileRecord* before = had ? old->output(path) : nullptr;
    if (before && before->hash == now.hash) continue;
    if (state::is_state_path(path)) continue;
    files.push_back(path);
    accepted.push_back({{"path", path},
                        {"hash", now.hash},
                        {"replaced_hash", before ? before->hash : std::string()},
                        {"accepted_utc", utc_now_iso8601()}});
  }
  if (files.empty() && had) return files;
  manifest["version"] = vesica::version();
  manifest["invocation"] = s.argv;
  manifest["inputs"] = inputs;
  manifest["outputs"] = outputs;
  manifest["accepted_edits"] = accepted;
  write_text_atomically(plan.in_workdir(s.manifest), manifest.dump(2) + "\n");
  clear_stage_failure(plan, s.id);
  return files;
}

}  // namespace vesica::pipelines
