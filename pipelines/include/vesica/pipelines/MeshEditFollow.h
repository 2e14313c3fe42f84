#pragma once
// A mesh edited in Gmsh and kept by the runner. vesica-mesh writes a .vtu beside its .msh
// for ParaView, which would go on showing the wall before the edit (and a report quoting
// the old mesh). Before the stages after it run, the runner has vesica-mesh make that .vtu
// follow the edited .msh (`vesica-mesh bladder.msh -o bladder.msh`: the fields Gmsh drops,
// thickness and fibers, recomputed and named in its warning). What it followed is recorded
// in the state folder (.vesica/<stage>.follow.manifest.json), so that it is done once per
// edit.
#include <functional>
#include <string>

#include "vesica/pipelines/Plan.h"

namespace vesica::pipelines {

// For stage `index` of tool "mesh" whose .msh output was edited: runs the follow-up when
// the .vtu has not yet followed this .msh. `say` gets the runner's lines and the tool's
// output. Returns false when the tool failed (said, and the run goes on with the edit).
bool follow_kept_mesh_edit(const Plan& plan, std::size_t index,
                           const std::function<void(const std::string&)>& say);

}  // namespace vesica::pipelines
