#pragma once
// Reads the wall for the simulation through vesica_io (SI units out):
//  - the .msh of vesica-mesh (vesica/io/MshFile.h), read as .msh: a mesh edited in Gmsh
//    (nodes moved, physical groups kept) is what is simulated;
//  - the .vtu beside it (vesica/io/VtuFile.h);
//  - a surface .vtp/.stl/.ply/.obj, tagged as vesica-mesh reads it (mesh/SurfaceReader.h:
//    sidecar, edit rule, automatic outlet).
// Thickness and fibers come from the file's element data when present (and, for a .msh,
// consistent with its geometry); a mesh without them gets the mesh stage's own defaults
// for its geometry (mesh::membrane_fields with default_thickness_m). A surface keeps
// default_thickness_m and no fibers. Coordinates are millimetres, converted to metres.
#include <filesystem>

#include "vesica/simulate/fluid/FluidMesh.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// Throws vesica::Error naming the file for a missing/unreadable file, no triangles, or an
// open surface.
WallModel read_wall(const std::filesystem::path& path, double default_thickness_m);

// The urine tetrahedra of a vesica-mesh --fluid .msh or .vtu in m, numbered so that nodes
// 0..N-1 are read_wall's wall nodes (same order, same positions) and the other tet points
// follow. Throws vesica::Error naming the file when it holds no tetrahedra.
fluid::FluidMesh read_urine(const std::filesystem::path& path);

}  // namespace vesica::simulate
