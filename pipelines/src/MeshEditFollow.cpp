#include "vesica/pipelines/MeshEditFollow.h"

#include "vesica/core/Error.h"
#include "vesica/core/StageRecord.h"
#include "vesica/pipelines/ChildProcess.h"
#include "vesica/pipelines/StageManifest.h"
#include "vesica/pipelines/StateFolder.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {

bool follow_kept_mesh_edit(const Plan& plan, std::size_t index,
                           const std::function<void(const std::string&)>& say) {
  const PlannedStage& s = plan.stages[index];
  const fs::path msh = plan.in_workdir(s.output);
  if (s.tool != "mesh" || msh.extension() != ".msh") return true;
  const fs::path vtu = msh.parent_path() / (msh.stem().string() + ".vtu");
  if (!fs::exists(msh) || !fs::exists(vtu)) return true;
  const fs::path record = plan.workdir / state::kFolder / (s.id + ".follow.manifest.json");
  const FileRecord now = record_file(msh);
  if (const auto done = read_stage_manifest(record);
      done && done->readable() && !done->inputs.empty() && done->inputs.front().hash == now.hash)
    return true;
  say("vesica: " + s.id + ": " + vtu.filename().string() + " follows your edit of " + s.output);
  try {
    ChildProcess tool(s.executable,
                      {msh.string(), "-o", msh.string(), "--manifest", record.string()},
                      plan.workdir);
    ChildOutput out;
    for (bool open = true; open;) {
      out.lines.clear();
      open = tool.read(out);
      for (const std::string& line : out.lines) say("  [" + s.id + "] " + line);
    }
    if (tool.wait() == 0) return true;
  } catch (const Error& e) {
    say(std::string("  [") + s.id + "] " + e.what());
  }
  say("vesica: warning: " + vtu.filename().string() + " could not follow " + s.output +
      ": it shows the mesh before your edit");
  return false;
}

}  // namespace vesica::pipelines
