#include "vesica/mesh/SurfaceReader.h"

#include <utility>

#include "vesica/core/Log.h"
#include "vesica/io/SurfaceFile.h"
#include "vesica/surface/SurfaceIO.h"
#include "vesica/surface/SurfaceRegions.h"

namespace vesica::mesh {

SurfaceMesh to_surface_mesh(io::TaggedSurface surface) {
  SurfaceMesh s;
  s.points = std::move(surface.points_mm);
  s.triangles = std::move(surface.triangles);
  s.region = std::move(surface.region);
  return s;
}

SurfaceMesh read_surface(const std::filesystem::path& path, std::vector<std::string>* notes) {
  io::SurfaceFile file = io::read_surface_file(path);
  if (!file.surface.has_regions()) {
    // The same regions vesica-surface gives an untagged surface with its default options.
    surface::TriangleSurface tagged = surface::from_tagged(std::move(file.surface));
    const surface::RegionOptions automatic;
    surface::assign_regions(automatic, tagged);
    file.surface = surface::to_tagged(tagged);
    file.notes.push_back(path.string() +
                         ": the outlet is placed automatically (most inferior point, " +
                         fmt::format("{:g}", automatic.outlet_radius_mm) + " mm patch)");
    log()->warn("{}", file.notes.back());
  }
  if (notes) notes->insert(notes->end(), file.notes.begin(), file.notes.end());
  return to_surface_mesh(std::move(file.surface));
}

}  // namespace vesica::mesh
