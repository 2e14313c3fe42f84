#pragma once
// A stage's manifest as the runner reads it back (written by vesica::StageRecord at the end
// of the stage, or by `vesica accept`), and how a file it records compares with the disk.
// Hashes are only recomputed when a file's size or modification time changed, so that a
// pipeline whose stages are all fresh is checked without reading any large file.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/core/StageRecord.h"

namespace vesica::pipelines {

struct StageManifest {
  nlohmann::json json;  // as read; not an object when the file is unreadable
  std::vector<FileRecord> inputs, outputs;
  // Outputs whose edit the user made the stage's own (`vesica accept`): still the user's
  // work, so they are set aside like an edit before the stage ever replaces them.
  std::vector<std::string> accepted;
  std::filesystem::file_time_type written{};  // the manifest file's modification time

  bool readable() const { return json.is_object(); }
  const FileRecord* output(const std::string& path) const;
};

// Whether `records` say what is at `path`: a record of it, or of files inside it (a stage
// writing a folder may record the files it wrote there, as vesica-simulate does).
bool recorded(const std::vector<FileRecord>& records, const std::string& path);

// True for a relative path that stays inside the workdir ("a/b", not "/x", "..", "../x"):
// what an output record of a manifest or failure record must be to be trusted.
bool stays_inside_workdir(const std::string& path);

// nullopt when there is no manifest at `path`.
std::optional<StageManifest> read_stage_manifest(const std::filesystem::path& path);

enum class FileState { Same, Changed, Missing, Unreadable };

// `path` against its record. The recorded hash is trusted while size and mtime are
// unchanged (for folders with an unusable recorded mtime: while nothing inside is newer
// than the manifest, `manifest_time`).
FileState compare_with_record(const std::filesystem::path& path, const FileRecord& recorded,
                              std::filesystem::file_time_type manifest_time);

// "changed", "missing", "unreadable"; "" for Same.
const char* to_string(FileState state);

}  // namespace vesica::pipelines
