#include "vesica/pipelines/StageManifest.h"

#include <algorithm>

#include "vesica/core/ContentHash.h"
#include "vesica/core/JsonFile.h"
#include "vesica/pipelines/PathIndex.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

// vesica_core 0.1 sums folder stamps with max(0, mtime) while libstdc++'s file_clock
// counts from an epoch after today, so a folder's recorded mtime is just a small count and
// cannot tell an edit that keeps the folder's size. A real mtime in ns is far larger.
bool stamp_is_trustworthy(const FileRecord& r) {
  return r.mtime_ns > 1'000'000'000'000LL || r.mtime_ns < -1'000'000'000'000LL;
}

// For such folders: nothing inside (files, subfolders, the folder itself) was modified
// after the manifest was written, which happens after the stage wrote its outputs.
bool folder_untouched_since(const fs::path& dir, fs::file_time_type manifest_time) {
  std::error_code ec;
  if (fs::last_write_time(dir, ec) > manifest_time || ec) return false;
  for (const auto& e : fs::recursive_directory_iterator(dir, ec))
    if (e.last_write_time(ec) > manifest_time || ec) return false;
  return !ec;
}

std::vector<FileRecord> records(const nlohmann::json& list) {
  std::vector<FileRecord> out;
  if (list.is_array())
    for (const auto& j : list)
      if (j.is_object()) out.push_back(file_record_from_json(j));
  return out;
}

// A stage's outputs are inside its workdir: a record naming a place outside (an edited or
// damaged manifest) is dropped, so that no backup or check ever reaches there.
std::vector<FileRecord> inside_workdir(std::vector<FileRecord> list) {
  list.erase(std::remove_if(list.begin(), list.end(),
                            [](const FileRecord& r) { return !stays_inside_workdir(r.path); }),
             list.end());
  return list;
}

}  // namespace

const FileRecord* StageManifest::output(const std::string& path) const {
  for (const auto& r : outputs)
    if (r.path == path) return &r;
  return nullptr;
}

bool recorded(const std::vector<FileRecord>& records, const std::string& path) {
  return std::any_of(records.begin(), records.end(),
                     [&](const FileRecord& r) { return inside_or_equal(r.path, path); });
}

bool stays_inside_workdir(const std::string& path) {
  const fs::path p = fs::path(path).lexically_normal();
  return !path.empty() && !p.is_absolute() && p != ".." && (p.empty() || *p.begin() != "..");
}

std::optional<StageManifest> read_stage_manifest(const fs::path& path) {
  auto json = read_json_file(path);
  if (!json) return std::nullopt;
  StageManifest m;
  m.json = std::move(*json);
  if (!m.readable()) return m;
  std::error_code ec;
  m.written = fs::last_write_time(path, ec);
  const nlohmann::json discarded(nlohmann::json::value_t::discarded);
  if ((m.json.contains("version") && !m.json["version"].is_string()) ||
      (m.json.contains("invocation") && !m.json["invocation"].is_array())) {
    m.json = discarded;  // not a manifest vesica wrote
    return m;
  }
  try {
    m.inputs = records(m.json.value("inputs", nlohmann::json()));
    m.outputs = inside_workdir(records(m.json.value("outputs", nlohmann::json())));
    for (const auto& a : m.json.value("accepted_edits", nlohmann::json::array()))
      if (a.is_object() && a.contains("path") && a["path"].is_string())
        m.accepted.push_back(a["path"].get<std::string>());
  } catch (const nlohmann::json::exception&) {  // a field of the wrong type: not vesica's
    m.json = discarded;
  }
  return m;
}

FileState compare_with_record(const fs::path& path, const FileRecord& recorded,
                              fs::file_time_type manifest_time) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return FileState::Missing;
  FileStamp now;
  try {
    now = file_stamp(path);
  } catch (const std::exception&) {
    return FileState::Unreadable;
  }
  if (now.size == recorded.size) {
    if (stamp_is_trustworthy(recorded) && now.mtime_ns == recorded.mtime_ns) return FileState::Same;
    if (!stamp_is_trustworthy(recorded) && fs::is_directory(path, ec) &&
        folder_untouched_since(path, manifest_time))
      return FileState::Same;
  }
  try {
    return content_hash(path) == recorded.hash ? FileState::Same : FileState::Changed;
  } catch (const std::exception&) {
    return FileState::Unreadable;
  }
}

const char* to_string(FileState state) {
  switch (state) {
    case FileState::Same:
      return "";
    case FileState::Changed:
      return "changed";
    case FileState::Missing:
      return "missing";
    case FileState::Unreadable:
      return "unreadable";
  }
  return "";
}

}  // namespace vesica::pipelines
