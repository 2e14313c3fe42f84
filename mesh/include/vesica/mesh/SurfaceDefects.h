#pragma once
// What makes a surface unusable as the boundary of the urine: holes (boundary edges),
// edges shared by more than two triangles, inconsistent orientation, zero-area
// triangles and self-intersections. All are counted so that one error lists them all.
#include <cstddef>
#include <string>

#include "vesica/mesh/SurfaceMesh.h"

namespace vesica::mesh {

struct SurfaceDefects {
  std::size_t boundary_edges = 0;
  std::size_t nonmanifold_edges = 0;
  std::size_t misoriented_edges = 0;  // edges whose two triangles traverse it the same way
  std::size_t degenerate_triangles = 0;
  std::size_t self_intersecting_pairs = 0;
  bool self_intersections_checked = false;  // skipped when the surface is not a manifold

  bool ok() const;
  // "3 boundary edges, 1 self-intersecting triangle pair" (only the non-zero ones).
  std::string describe() const;
};

// Counts the defects; self-intersections via CGAL when the surface is a manifold.
SurfaceDefects find_surface_defects(const SurfaceMesh& surface);

// Throws vesica::Error(file, "surface is not closed/manifold/...: <defects>") unless ok().
void require_valid_surface(const SurfaceMesh& surface, const std::string& file);

}  // namespace vesica::mesh
