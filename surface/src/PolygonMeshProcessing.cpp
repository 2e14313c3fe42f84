// The only CGAL translation unit of vesica's surface stage.
#include "vesica/surface/PolygonMeshProcessing.h"

#include <array>
#include <cstddef>
#include <iterator>
#include <map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include "vesica/surface/Topology.h"

namespace vesica::surface {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

// Builds a half-edge mesh through a polygon soup, which orients the triangles
// consistently and splits non-manifold vertices instead of failing.
Mesh to_mesh(const TriangleSurface& surface) {
  std::vector<Point> points;
  points.reserve(surface.V.rows());
  for (Eigen::Index v = 0; v < surface.V.rows(); ++v)
    points.emplace_back(surface.V(v, 0), surface.V(v, 1), surface.V(v, 2));
  std::vector<std::array<std::size_t, 3>> triangles;
  triangles.reserve(surface.F.rows());
  for (Eigen::Index f = 0; f < surface.F.rows(); ++f)
    triangles.push_back({static_cast<std::size_t>(surface.F(f, 0)),
                         static_cast<std::size_t>(surface.F(f, 1)),
                         static_cast<std::size_t>(surface.F(f, 2))});
  PMP::orient_polygon_soup(points, triangles);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, triangles, mesh);
  return mesh;
}

TriangleSurface from_mesh(Mesh mesh) {
  mesh.collect_garbage();
  TriangleSurface out;
  out.V.resize(mesh.number_of_vertices(), 3);
  for (auto v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    out.V.row(v.idx()) << p.x(), p.y(), p.z();
  }
  out.F.resize(mesh.number_of_faces(), 3);
  for (auto f : mesh.faces()) {
    int k = 0;
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) out.F(f.idx(), k++) = v.idx();
  }
  return out;
}

bool has_non_manifold_vertex(const Mesh& mesh) {
  for (auto v : mesh.vertices())
    if (PMP::is_non_manifold_vertex(v, mesh)) return true;
  return false;
}

int count_components(Mesh& mesh) {
  auto component = mesh.add_property_map<Mesh::Face_index, std::size_t>("f:cc").first;
  const std::size_t n = PMP::connected_components(mesh, component);
  return static_cast<int>(n);
}

std::string fill_small_holes(double max_perimeter_mm, Mesh& mesh) {
  std::vector<Mesh::Halfedge_index> border_cycles;
  PMP::extract_boundary_cycles(mesh, std::back_inserter(border_cycles));
  int filled = 0, left = 0;
  for (auto h : border_cycles) {
    double perimeter = 0.0;
    for (auto e : CGAL::halfedges_around_face(h, mesh)) perimeter += PMP::edge_length(e, mesh);
    if (perimeter > max_perimeter_mm) {
      ++left;
      continue;
    }
    std::vector<Mesh::Face_index> faces;
    std::vector<Mesh::Vertex_index> vertices;
    PMP::triangulate_refine_and_fair_hole(mesh, h, std::back_inserter(faces),
                                          std::back_inserter(vertices));
    ++filled;
  }
  if (filled == 0 && left == 0) return "";
  return "filled " + std::to_string(filled) + " hole(s)" +
         (left ? ", left " + std::to_string(left) + " larger than the perimeter limit" : "");
}

}  // namespace

void remesh_isotropic(const RemeshOptions& options, TriangleSurface& surface) {
  Mesh mesh = to_mesh(surface);
  PMP::isotropic_remeshing(faces(mesh), options.edge_mm, mesh,
                           PMP::parameters::number_of_iterations(options.iterations)
                               .number_of_relaxation_steps(options.relaxation_steps));
  surface = from_mesh(std::move(mesh));
}

std::string SurfaceChecks::first_failure() const {
  if (!closed)
    return "surface is open: " + std::to_string(boundary_edges) + " boundary edges in " +
           std::to_string(holes) + " hole(s)";
  if (!manifold)
    return "surface is not 2-manifold: " + std::to_string(non_manifold_edges) +
           " non-manifold edges";
  if (self_intersections) return "surface intersects itself";
  if (components != 1) return "surface has " + std::to_string(components) + " components";
  if (!outward) return "surface is oriented inward";
  return "";
}

SurfaceChecks check_surface(const TriangleSurface& surface) {
  SurfaceChecks checks;
  const EdgeTopology topology = edge_topology(surface.F);
  checks.boundary_edges = topology.boundary_edges;
  checks.holes = topology.holes;
  checks.non_manifold_edges = topology.non_manifold_edges;
  checks.closed = topology.closed();
  if (!topology.edge_manifold() || topology.inconsistent_edges > 0) return checks;
  Mesh mesh = to_mesh(surface);
  checks.manifold = !has_non_manifold_vertex(mesh) &&
                    mesh.number_of_vertices() == static_cast<std::size_t>(surface.V.rows());
  checks.self_intersections = PMP::does_self_intersect(mesh);
  checks.components = count_components(mesh);
  checks.outward = checks.closed && enclosed_volume(surface.V, surface.F) > 0;
  return checks;
}

std::vector<std::string> repair_surface(const RepairOptions& options, TriangleSurface& surface) {
  std::vector<std::string> notes;
  const EdgeTopology before = edge_topology(surface.F);
  Mesh mesh = to_mesh(surface);
  if (before.inconsistent_edges > 0)
    notes.push_back("made the orientation of " + std::to_string(before.inconsistent_edges) +
                    " inconsistent edges consistent");
  const int components = count_components(mesh);
  if (components > 1) {
    PMP::keep_largest_connected_components(mesh, 1);
    notes.push_back("removed " + std::to_string(components - 1) +
                    " component(s) besides the largest");
  }
  if (options.fill_holes && !CGAL::is_closed(mesh)) {
    const std::string note = fill_small_holes(options.max_hole_perimeter_mm, mesh);
    if (!note.empty()) notes.push_back(note);
  }
  if (CGAL::is_closed(mesh) && !PMP::is_outward_oriented(mesh)) {
    PMP::reverse_face_orientations(mesh);
    notes.push_back("normals pointed inward; reversed the triangle orientation");
  }
  surface = from_mesh(std::move(mesh));
  return notes;
}

}  // namespace vesica::surface
