#include "vesica/mesh/SurfaceDefects.h"

#include <map>
#include <utility>
#include <vector>

#include "vesica/core/Error.h"
#include "vesica/mesh/SelfIntersections.h"

namespace vesica::mesh {

namespace {

void append(std::string& text, std::size_t count, const std::string& what) {
  if (count == 0) return;
  if (!text.empty()) text += ", ";
  text += std::to_string(count) + " " + what;
}

}  // namespace

bool SurfaceDefects::ok() const {
  return boundary_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 &&
         degenerate_triangles == 0 && self_intersecting_pairs == 0;
}

std::string SurfaceDefects::describe() const {
  std::string text;
  append(text, boundary_edges, "boundary edges (holes)");
  append(text, nonmanifold_edges, "non-manifold edges");
  append(text, misoriented_edges, "inconsistently oriented edges");
  append(text, degenerate_triangles, "zero-area triangles");
  append(text, self_intersecting_pairs, "self-intersecting triangle pairs");
  if (!self_intersections_checked)
    text += (text.empty() ? "" : "; ") + std::string("self-intersections not checked");
  return text.empty() ? "no defects" : text;
}

SurfaceDefects find_surface_defects(const SurfaceMesh& surface) {
  SurfaceDefects d;
  // Each undirected edge with the number of uses in each direction.
  std::map<std::pair<int, int>, std::pair<int, int>> edges;
  for (Eigen::Index t = 0; t < surface.triangles.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = surface.triangles(t, k), b = surface.triangles(t, (k + 1) % 3);
      auto& uses = edges[{std::min(a, b), std::max(a, b)}];
      (a < b ? uses.first : uses.second) += 1;
    }
  }
  for (const auto& [edge, uses] : edges) {
    const int total = uses.first + uses.second;
    if (total == 1) ++d.boundary_edges;
    if (total > 2) ++d.nonmanifold_edges;
    if (total == 2 && uses.first != 1) ++d.misoriented_edges;
  }
  const Eigen::VectorXd areas = triangle_areas_mm2(surface);
  for (Eigen::Index t = 0; t < areas.size(); ++t)
    if (!(areas(t) > 0.0)) ++d.degenerate_triangles;
  // CGAL needs an oriented 2-manifold to build its halfedge mesh.
  if (d.nonmanifold_edges == 0 && d.misoriented_edges == 0) {
    if (auto pairs = count_self_intersecting_pairs(surface.points, surface.triangles)) {
      d.self_intersecting_pairs = *pairs;
      d.self_intersections_checked = true;
    }
  }
  return d;
}

void require_valid_surface(const SurfaceMesh& surface, const std::string& file) {
  const SurfaceDefects d = find_surface_defects(surface);
  if (!d.ok())
    fail(file,
         "surface is not a closed, manifold, non-self-intersecting triangle surface: " +
             d.describe(),
         "repair it (vesica-surface) before meshing");
}

}  // namespace vesica::mesh
