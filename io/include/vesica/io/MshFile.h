#pragma once
// Gmsh .msh 4.1 (ASCII) of the bladder mesh, in mm, written and read through the gmsh API:
//  - 2-D physical groups "wall", "outlet", "inlet", "fixed", "support" (only non-empty
//    ones, tagged with their region code, vesica/core/Regions.h), the 3-D group "urine"
//    (tag 10) when there are tetrahedra;
//  - node tags = node index + 1, element tags = triangle index + 1 then the tetrahedra, so
//    that reading restores vesica's order;
//  - element data (views) "thickness_mm" and "fiber1", "fiber2" (3 components): the
//    triangles' values, 0 on the tetrahedra (as in the .vtu). Gmsh keeps a mesh's physical groups
//    when it saves an edit but not its views: read_msh then returns no thickness or fibers, and the
//    caller computes the mesh stage's defaults for the edited geometry.
// Coordinates are stored with gmsh's 16 significant digits.
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/io/VolumeMesh.h"

namespace vesica::io {

// Writes atomically; throws vesica::Error naming the file when gmsh reports an error.
void write_msh(const VolumeMesh& mesh, const std::filesystem::path& path);

struct MshFile {
  VolumeMesh mesh;                 // thickness/fibers empty when absent or inconsistent
  std::vector<std::string> notes;  // why element data were not used (also logged)
};

// Reads nodes, triangles (region from their physical group's name), tetrahedra and the
// element data above; element data are dropped with a note when they do not cover every
// triangle, are not finite, thickness is not positive, or a fiber is not a unit vector in
// its triangle's plane (the nodes were moved). Throws vesica::Error naming the file when it
// cannot be read, has no triangles, or a triangle's physical group is not a region name.
MshFile read_msh(const std::filesystem::path& path);

}  // namespace vesica::io
