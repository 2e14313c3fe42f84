#pragma once
// Internal to vesica_simulate: what a mesh must be before the FEM trusts it, checked when
// it is read (MeshReader.cpp), so that a broken or hostile file is refused with one line
// instead of being "simulated":
//  - arrays of the right width: a region, and a thickness or fiber frame either for every
//    triangle or for none; fiber frames of 3 components; node indices within the nodes;
//  - finite numbers: coordinates, thickness within the range below, unit fibers;
//  - the wall one closed component: every edge in two triangles of opposite orientation,
//    no zero-area triangle, no self-intersection, one connected surface;
//  - tetrahedra positively oriented (level 2).
#include <string>

#include "vesica/io/VolumeMesh.h"

namespace vesica::simulate::detail {

// Wall thickness a mesh may carry, mm: the mesh stage's own range.
inline constexpr double kMinThicknessMm = 0.1;
inline constexpr double kMaxThicknessMm = 30.0;

// Throws vesica::Error naming `file` for the first array problem.
void check_mesh_arrays(const io::VolumeMesh& mesh, const std::string& file);

// Throws vesica::Error naming `file` unless the triangles form one closed, manifold,
// consistently oriented surface without self-intersections.
void check_wall_surface(const io::VolumeMesh& mesh, const std::string& file);

// Throws vesica::Error naming `file` for a tetrahedron of zero or negative volume.
void check_tetrahedra(const io::VolumeMesh& mesh, const std::string& file);

}  // namespace vesica::simulate::detail
