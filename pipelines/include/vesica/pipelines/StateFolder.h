#pragma once
// Everything the runner keeps about a workdir lives in WORKDIR/.vesica/, out of the way of
// the user's files, named by one rule from the stage's id ("surface", "simulate@stiff"):
//   .vesica/<id>.manifest.json   the stage's manifest (the default `manifest:`)
//   .vesica/<id>.json            the stage's report (the default `report:`)
//   .vesica/<id>.failed.json     a stage that failed, was interrupted or is running
//                                (StageFailure.h)
//   .vesica/backup/<id>/<UTC time>/<output>   files set aside before they were replaced
//   .vesica/lock                 held by the `vesica` that works in the workdir
#include <filesystem>
#include <string>

namespace vesica::pipelines::state {

inline constexpr const char* kFolder = ".vesica";

// Workdir-relative paths.
std::string manifest_path(const std::string& id);
std::string report_path(const std::string& id);
std::string failure_path(const std::string& id);
std::string lock_path();
// The folder of one backup: .vesica/backup/<id>/<stamp>, `stamp` a UTC time.
std::string backup_folder(const std::string& id, const std::string& stamp);

// Makes WORKDIR/.vesica when missing. Throws vesica::Error when it is a symbolic link or
// not a folder: vesica's state, backups and lock are never written through a link.
void require_state_folder(const std::filesystem::path& workdir);

// True for `.vesica` and every path inside it.
bool is_state_path(const std::string& workdir_relative);

}  // namespace vesica::pipelines::state
