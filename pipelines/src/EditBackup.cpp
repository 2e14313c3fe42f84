#include "vesica/pipelines/EditBackup.h"

#include <algorithm>

#include "vesica/core/Error.h"
#include "vesica/pipelines/StageFailure.h"
#include "vesica/pipelines/StageManifest.h"
#include "vesica/pipelines/StateFolder.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

// What vesica knows it left at the stage's outputs: the manifest's records, or after a
// failure those the runner kept; nothing after a runner was killed outright.
struct Known {
  std::vector<FileRecord> records;
  std::vector<std::string> accepted;
  fs::file_time_type written = fs::file_time_type::min();
};

Known known_outputs(const Plan& plan, const PlannedStage& s) {
  Known k;
  if (const auto m = read_stage_manifest(plan.in_workdir(s.manifest)); m && m->readable()) {
    k.records = m->outputs;
    k.accepted = m->accepted;
    k.written = m->written;
  } else if (const auto f = read_stage_failure(plan, s.id);
             f && f->state != StageFailure::State::Running) {
    k.records = f->outputs_before;
  }
  return k;
}

// The stage's outputs that a user could have touched: the planned one, the files it
// writes beside it (declared by its tool: a sidecar, the .vtu beside a .msh, export_feb)
// and every recorded one, not vesica's own files under .vesica/.
std::vector<std::string> candidates(const PlannedStage& s, const Known& k) {
  std::vector<std::string> paths = {s.output};
  for (const auto& side : s.side_outputs)
    if (std::find(paths.begin(), paths.end(), side) == paths.end()) paths.push_back(side);
  for (const auto& r : k.records)
    if (std::find(paths.begin(), paths.end(), r.path) == paths.end()) paths.push_back(r.path);
  paths.erase(std::remove_if(paths.begin(), paths.end(),
                             [&](const std::string& p) {
                               return state::is_state_path(p) || p == s.report || p == s.manifest;
                             }),
              paths.end());
  return paths;
}

bool needs_backup(const Plan& plan, const std::string& path, const Known& k) {
  const auto record = std::find_if(k.records.begin(), k.records.end(),
                                   [&](const FileRecord& r) { return r.path == path; });
  // A folder whose recorded files are candidates of their own.
  if (record == k.records.end()) return !recorded(k.records, path);
  if (std::count(k.accepted.begin(), k.accepted.end(), path)) return true;
  return compare_with_record(plan.in_workdir(path), *record, k.written) == FileState::Changed;
}

}  // namespace

std::string backup_stamp() {
  std::string stamp = utc_now_iso8601();  // 2026-11-24T23:01:09Z
  stamp.erase(
      std::remove_if(stamp.begin(), stamp.end(), [](char c) { return c == '-' || c == ':'; }),
      stamp.end());
  return stamp;
}

Backup back_up_outputs(const Plan& plan, std::size_t index) {
  const PlannedStage& s = plan.stages[index];
  const Known known = known_outputs(plan, s);
  Backup backup;
  for (const auto& path : candidates(s, known)) {
    std::error_code ec;
    const fs::path source = plan.in_workdir(path);
    if (!fs::exists(fs::symlink_status(source, ec)) || !needs_backup(plan, path, known)) continue;
    if (backup.folder.empty()) {
      // Two backups of one stage within a second get folders of their own.
      const std::string stamp = backup_stamp();
      backup.folder = state::backup_folder(s.id, stamp);
      for (int n = 2; fs::exists(plan.in_workdir(backup.folder)); ++n)
        backup.folder = state::backup_folder(s.id, stamp + "-" + std::to_string(n));
    }
    const fs::path target = plan.in_workdir(backup.folder + "/" + path);
    fs::create_directories(target.parent_path(), ec);
    if (!ec)
      fs::copy(source, target, fs::copy_options::recursive | fs::copy_options::copy_symlinks, ec);
    if (ec)
      fail(source.string(), "cannot be saved to " + target.string() + " before " + s.id +
                                " replaces it (" + ec.message() + "); the stage was not started");
    backup.files.push_back(path);
  }
  return backup;
}

}  // namespace vesica::pipelines
