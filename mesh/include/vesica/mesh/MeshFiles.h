#pragma once
// The mesh files of the mesh stage. Both are written atomically (temporary name with the
// same extension, then rename).
//  - Gmsh .msh 4.1 in mm: 2-D physical groups "wall", "outlet", "inlet", "fixed",
//    "support" (only non-empty ones, tagged with their region code) and the 3-D group
//    "urine" (tag 10) when there are tetrahedra.
//  - VTK .vtu: triangles then tetrahedra; cell data "region" (Int32, tets = 10),
//    "thickness_mm" (Float64, tets 0), "fiber1", "fiber2" (3-vectors, tets 0); field
//    data "units" = "mm". This is what vesica-simulate reads.
#include <filesystem>

#include "vesica/mesh/VolumeMesh.h"

namespace vesica::mesh {

void write_msh(const VolumeMesh& mesh, const std::filesystem::path& path);
void write_vtu(const VolumeMesh& mesh, const std::filesystem::path& path);

// Reads a .vtu written by write_vtu (or any unstructured grid of triangles and
// tetrahedra in mm; missing arrays get defaults: wall, 3 mm, zero fibers).
VolumeMesh read_vtu(const std::filesystem::path& path);

// "<dir>/<stem>.vtu" beside a .msh path.
std::filesystem::path vtu_beside(const std::filesystem::path& msh_path);

}  // namespace vesica::mesh
