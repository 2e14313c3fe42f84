#pragma once
// The names of the files stages write beside their declared output, in one place: the
// stages write them under these names, and their parameter tables declare them to the
// runner (ParameterTable::beside_output), which backs them up like the output itself.
#include <string>

namespace vesica {

// "out/bladder.msh" -> "out/bladder.vtu": vesica-mesh's meshes for ParaView.
std::string vtu_beside_msh(const std::string& msh);

// "out/bladder.ply" -> "out/bladder.ply.regions.json": the region tags of a surface.
std::string regions_sidecar_name(const std::string& surface);
// Whether a surface file needs that sidecar: every format but .vtp, which carries its tags.
bool surface_needs_sidecar(const std::string& surface);

}  // namespace vesica
