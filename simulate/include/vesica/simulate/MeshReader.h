#pragma once
// Reads the wall for the simulation (SI units out):
//  - the .vtu written by vesica-mesh: triangles = wall elements with cell data "region",
//    "thickness_mm", "fiber1", "fiber2"; tetrahedra (urine) are ignored at level 1;
//  - a .msh: the sibling .vtu with the same stem is read;
//  - a surface .vtp (cell array "region") or .stl (every triangle "wall").
// Coordinates are millimetres (field data "units" = "mm") and converted to metres.
#include <filesystem>

#include "vesica/simulate/WallModel.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate {

// default_thickness_m applies where the file has no "thickness_mm". Throws vesica::Error
// naming the file for a missing/unreadable file, no triangles, or an open surface.
WallModel read_wall(const std::filesystem::path& path, double default_thickness_m);

// The urine tetrahedra of a vesica-mesh --fluid .vtu (or its .msh) in m, numbered so that
// nodes 0..N-1 are read_wall's wall nodes (same order, same positions) and the other tet
// points follow. Throws vesica::Error naming the file when it holds no tetrahedra.
fluid::FluidMesh read_urine(const std::filesystem::path& path);

}  // namespace vesica::simulate
