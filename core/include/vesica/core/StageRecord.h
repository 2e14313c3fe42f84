#pragma once
// What one run of a stage leaves behind besides its outputs:
//  - a summary JSON with the numbers a user asks first (volumes in ml, counts, timings);
//  - a manifest JSON with the tool version, the exact invocation, the effective
//    parameters and the content hashes of every input and output. The runner compares
//    manifests with the files on disk to decide what is stale.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace vesica {

const char* version();

struct FileRecord {
  std::string path;  // as given on the command line
  std::string hash;  // content_hash()
  std::uintmax_t size = 0;
  std::int64_t mtime_ns = 0;
};
FileRecord record_file(const std::filesystem::path& path);
nlohmann::json to_json(const FileRecord& f);
FileRecord file_record_from_json(const nlohmann::json& j);

class StageRecord {
 public:
  // argv is kept verbatim (less the program path) as the invocation.
  StageRecord(std::string tool, int argc, const char* const* argv);

  nlohmann::json& parameters() { return parameters_; }
  // The stage's own numbers; "tool", "version" and "timings_s" are added on write.
  nlohmann::json& summary() { return summary_; }

  void add_input(const std::filesystem::path& path);
  void add_output(const std::filesystem::path& path);
  // Seconds spent in a named phase ("read", "segment", "write").
  void add_timing(const std::string& phase, double seconds);
  double elapsed_seconds() const;

  // Hashes the outputs and writes the summary and manifest atomically; either path
  // may be empty to skip it. Returns the summary as written.
  nlohmann::json write(const std::filesystem::path& summary_path,
                       const std::filesystem::path& manifest_path);

 private:
  std::string tool_;
  std::vector<std::string> invocation_;
  nlohmann::json parameters_ = nlohmann::json::object();
  nlohmann::json summary_ = nlohmann::json::object();
  nlohmann::json timings_ = nlohmann::json::object();
  std::vector<FileRecord> inputs_;
  std::vector<std::filesystem::path> outputs_;
  std::chrono::steady_clock::time_point start_;
  std::string started_utc_;
};

// Measures the time of a scope into a StageRecord phase.
class PhaseTimer {
 public:
  PhaseTimer(StageRecord& record, std::string phase);
  ~PhaseTimer();
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  StageRecord& record_;
  std::string phase_;
  std::chrono::steady_clock::time_point start_;
};

std::string utc_now_iso8601();

}  // namespace vesica
