#pragma once
// The bladder surface the mesh stage starts from, read through vesica_io
// (vesica/io/SurfaceFile.h: .vtp, .stl, .ply, .obj in mm, the regions sidecar, the one
// re-tagging rule for an edited surface). A file without region tags gets the automatic
// outlet of vesica-surface (--outlet auto: the most inferior point, default radius), with
// a warning: a wall is never meshed without an outlet by accident.
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/io/TaggedSurface.h"
#include "vesica/mesh/SurfaceMesh.h"

namespace vesica::mesh {

// Throws vesica::Error naming `path` when the file is missing, unreadable, not in mm,
// has no triangles or carries unknown region codes. What the reader noticed about the
// tags (re-tagged after an edit, automatic outlet) goes to `notes` when given.
SurfaceMesh read_surface(const std::filesystem::path& path,
                         std::vector<std::string>* notes = nullptr);

SurfaceMesh to_surface_mesh(io::TaggedSurface surface);

}  // namespace vesica::mesh
