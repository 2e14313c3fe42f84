#pragma once
// CGAL Polygon Mesh Processing on a TriangleSurface: isotropic remeshing, the checks a
// surface must pass before it is written, and the repairs that make it pass. All CGAL
// code of vesica lives behind this header in one translation unit (it compiles slowly).
// Region tags do not survive these operations (the triangles change); assign regions after.
#include <string>
#include <vector>

#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

struct RemeshOptions {
  double edge_mm = 4.0;  // target edge length
  int iterations = 5;    // split/collapse/flip/relax rounds
  int relaxation_steps = 3;
};

// CGAL::Polygon_mesh_processing::isotropic_remeshing of a closed surface.
void remesh_isotropic(const RemeshOptions& options, TriangleSurface& surface);

struct SurfaceChecks {
  bool closed = false;
  bool manifold = false;  // 2-manifold: every edge in two triangles, every vertex one fan
  bool self_intersections = true;
  int components = 0;
  bool outward = false;
  int boundary_edges = 0;
  int holes = 0;
  int non_manifold_edges = 0;
  bool passed() const {
    return closed && manifold && !self_intersections && components == 1 && outward;
  }
  std::string first_failure() const;  // "" when passed()
};

SurfaceChecks check_surface(const TriangleSurface& surface);

// Repairs, each returning what it did as a note for the report ("" when nothing).
struct RepairOptions {
  bool fill_holes = false;
  double max_hole_perimeter_mm = 60.0;  // only holes up to this boundary length are filled
};
// Makes the triangle orientation consistent and outward, keeps the largest connected
// component, fills small holes when asked. Input must be edge-manifold.
std::vector<std::string> repair_surface(const RepairOptions& options, TriangleSurface& surface);

}  // namespace vesica::surface
