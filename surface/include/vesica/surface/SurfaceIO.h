#pragma once
// The surface stage's view of vesica_io's surface files (vesica/io/SurfaceFile.h: formats,
// units, the regions sidecar and the one rule for an edited surface's tags), as
// TriangleSurface.
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/io/RegionsSidecar.h"
#include "vesica/io/SurfaceFile.h"
#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

using WriteOptions = io::SurfaceWriteOptions;
using io::is_surface_file;
using io::regions_sidecar_path;

// Throws vesica::Error naming the file when it cannot be read or holds no triangles.
// `region` is the file's tags (re-tagged after an edit) or empty when it has none; what the
// reader noticed about them goes to `notes` when given.
TriangleSurface read_surface(const std::filesystem::path& path,
                             std::vector<std::string>* notes = nullptr);

// Writes atomically (and the sidecar for formats without cell data).
void write_surface(const TriangleSurface& surface, const std::filesystem::path& path,
                   const WriteOptions& options = {});

io::TaggedSurface to_tagged(const TriangleSurface& surface);
TriangleSurface from_tagged(io::TaggedSurface surface);

}  // namespace vesica::surface
