#include "vesica/core/StageRecord.h"

#include <ctime>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/ContentHash.h"
#include "vesica/core/Error.h"
#include "vesica/core/StagedOutputs.h"
#include "vesica/core/Version.h"

namespace fs = std::filesystem;

namespace vesica {

const char* version() {
  return kVersion;
}

std::string utc_now_iso8601() {
  const std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

FileRecord record_file(const fs::path& path) {
  // An output of this run may still wait under its temporary name (StagedOutputs.h); the
  // rename keeps its content and modification time.
  const fs::path content = staged_content(path).value_or(path);
  if (!fs::exists(content)) fail(path.string(), "does not exist");
  FileRecord f;
  f.path = path.string();
  f.hash = content_hash(content);
  const FileStamp s = file_stamp(content);
  f.size = s.size;
  f.mtime_ns = s.mtime_ns;
  return f;
}

nlohmann::json to_json(const FileRecord& f) {
  return {{"path", f.path}, {"hash", f.hash}, {"size", f.size}, {"mtime_ns", f.mtime_ns}};
}

FileRecord file_record_from_json(const nlohmann::json& j) {
  FileRecord f;
  f.path = j.value("path", "");
  f.hash = j.value("hash", "");
  f.size = j.value("size", std::uintmax_t{0});
  f.mtime_ns = j.value("mtime_ns", std::int64_t{0});
  return f;
}

StageRecord::StageRecord(std::string tool, int argc, const char* const* argv)
    : tool_(std::move(tool)),
      start_(std::chrono::steady_clock::now()),
      started_utc_(utc_now_iso8601()) {
  for (int i = 1; i < argc; ++i) invocation_.emplace_back(argv[i]);
}

void StageRecord::add_input(const fs::path& path) {
  inputs_.push_back(record_file(path));
}
void StageRecord::add_output(const fs::path& path) {
  outputs_.push_back(path);
}

void StageRecord::add_timing(const std::string& phase, double seconds) {
  timings_[phase] = timings_.value(phase, 0.0) + seconds;
}

double StageRecord::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

nlohmann::json StageRecord::write(const fs::path& summary_path, const fs::path& manifest_path) {
  nlohmann::json timings = timings_;
  timings["total"] = elapsed_seconds();

  nlohmann::json summary = summary_;
  summary["tool"] = tool_;
  summary["version"] = version();
  summary["timings_s"] = timings;
  if (!summary_path.empty()) write_text_atomically(summary_path, summary.dump(2) + "\n");

  if (!manifest_path.empty()) {
    nlohmann::json inputs = nlohmann::json::array();
    for (const auto& f : inputs_) inputs.push_back(to_json(f));
    nlohmann::json outputs = nlohmann::json::array();
    for (const auto& p : outputs_) outputs.push_back(to_json(record_file(p)));
    if (!summary_path.empty()) outputs.push_back(to_json(record_file(summary_path)));
    nlohmann::json manifest = {{"tool", tool_},
                               {"version", version()},
                               {"invocation", invocation_},
                               {"parameters", parameters_},
                               {"inputs", inputs},
                               {"outputs", outputs},
                               {"started_utc", started_utc_},
                               {"finished_utc", utc_now_iso8601()},
                               {"timings_s", timings}};
    write_text_atomically(manifest_path, manifest.dump(2) + "\n");
  }
  return summary;
}

PhaseTimer::PhaseTimer(StageRecord& record, std::string phase)
    : record_(record), phase_(std::move(phase)), start_(std::chrono::steady_clock::now()) {}

PhaseTimer::~PhaseTimer() {
  record_.add_timing(
      phase_, std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count());
}

}  // namespace vesica
