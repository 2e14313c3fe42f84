#include "vesica/core/SideOutputNames.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace vesica {

std::string vtu_beside_msh(const std::string& msh) {
  const std::filesystem::path p(msh);
  return (p.parent_path() / (p.stem().string() + ".vtu")).string();
}

std::string regions_sidecar_name(const std::string& surface) {
  return surface + ".regions.json";
}

bool surface_needs_sidecar(const std::string& surface) {
  std::string ext = std::filesystem::path(surface).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext != ".vtp";
}

}  // namespace vesica
