#include "vesica/surface/SurfaceIO.h"

#include <utility>

namespace vesica::surface {

io::TaggedSurface to_tagged(const TriangleSurface& surface) {
  return {surface.V, surface.F, surface.region};
}

TriangleSurface from_tagged(io::TaggedSurface surface) {
  TriangleSurface out;
  out.V = std::move(surface.points_mm);
  out.F = std::move(surface.triangles);
  out.region = std::move(surface.region);
  return out;
}

TriangleSurface read_surface(const std::filesystem::path& path, std::vector<std::string>* notes) {
  io::SurfaceFile file = io::read_surface_file(path);
  if (notes) notes->insert(notes->end(), file.notes.begin(), file.notes.end());
  return from_tagged(std::move(file.surface));
}

void write_surface(const TriangleSurface& surface, const std::filesystem::path& path,
                   const WriteOptions& options) {
  io::write_surface_file(to_tagged(surface), path, options);
}

}  // namespace vesica::surface
