#pragma once
// Region tags of the bladder wall, shared by surface (VTP cell array "region" and JSON
// sidecar), mesh (Gmsh physical groups named as below) and simulate (supports, caps).
// Every wall triangle carries exactly one tag.
#include <array>
#include <optional>
#include <string_view>

namespace vesica {

enum class Region : int {
  Wall = 1,     // free bladder wall
  Outlet = 2,   // bladder neck patch; a fixed cap in the level-1 model, the outflow patch later
  Inlet = 3,    // ureter orifice patches
  Fixed = 4,    // base / trigone held in place
  Support = 5,  // elastic support (pelvic floor springs)
};
inline constexpr int kUrineVolumeTag = 10;  // tetrahedra of the urine ("urine")

inline constexpr std::array<Region, 5> kAllRegions = {Region::Wall, Region::Outlet, Region::Inlet,
                                                      Region::Fixed, Region::Support};

constexpr std::string_view region_name(Region r) {
  switch (r) {
    case Region::Wall: return "wall";
    case Region::Outlet: return "outlet";
    case Region::Inlet: return "inlet";
    case Region::Fixed: return "fixed";
    case Region::Support: return "support";
  }
  return "wall";
}

inline std::optional<Region> region_from_name(std::string_view name) {
  for (Region r : kAllRegions)
    if (region_name(r) == name) return r;
  return std::nullopt;
}

}  // namespace vesica
