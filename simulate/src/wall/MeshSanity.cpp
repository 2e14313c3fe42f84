#include "wall/MeshSanity.h"

#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

#include <Eigen/Geometry>

#include "vesica/core/Error.h"
#include "vesica/mesh/SurfaceDefects.h"

namespace vesica::simulate::detail {
namespace {

// Unit length of a fiber direction within this (vesica-mesh writes them to 1e-15).
constexpr double kFiberUnitTolerance = 1e-3;

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string element(const char* what, Eigen::Index i) {
  return std::string(what) + " " + std::to_string(i);
}

void check_indices(const Eigen::MatrixXi& cells, const char* what, Eigen::Index nodes,
                   const std::string& file) {
  for (Eigen::Index c = 0; c < cells.rows(); ++c)
    for (Eigen::Index k = 0; k < cells.cols(); ++k)
      if (cells(c, k) < 0 || cells(c, k) >= nodes)
        fail(file, element(what, c) + " names node " + std::to_string(cells(c, k)) + " of " +
                       std::to_string(nodes));
}

void check_width(Eigen::Index rows, Eigen::Index triangles, const char* array,
                 const std::string& file) {
  if (rows != 0 && rows != triangles)
    fail(file, std::string(array) + " has " + std::to_string(rows) + " values for " +
                   std::to_string(triangles) + " triangles");
}

void check_fibers(const Eigen::MatrixXd& fibers, const char* array, const std::string& file) {
  if (fibers.rows() > 0 && fibers.cols() != 3)
    fail(file,
         std::string(array) + " has " + std::to_string(fibers.cols()) + " components, expected 3");
  for (Eigen::Index t = 0; t < fibers.rows(); ++t) {
    const double norm = fibers.row(t).norm();
    if (!std::isfinite(norm) || std::abs(norm - 1.0) > kFiberUnitTolerance)
      fail(file,
           std::string(array) + " of " + element("triangle", t) + " is not a finite unit vector");
  }
}

// Connected pieces of the surface (triangles sharing a node are connected).
int surface_components(const io::VolumeMesh& m) {
  std::vector<int> parent(static_cast<std::size_t>(m.nodes.rows()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t)
    for (int k = 1; k < 3; ++k) parent[root(m.triangles(t, k))] = root(m.triangles(t, 0));
  std::vector<bool> used(parent.size(), false), counted(parent.size(), false);
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) used[m.triangles(t, 0)] = true;
  int components = 0;
  for (std::size_t i = 0; i < parent.size(); ++i)
    if (used[i] && !counted[root(static_cast<int>(i))]) {
      counted[root(static_cast<int>(i))] = true;
      ++components;
    }
  return components;
}

}  // namespace

void check_mesh_arrays(const io::VolumeMesh& m, const std::string& file) {
  const Eigen::Index n = m.nodes.rows(), t = m.triangles.rows();
  if (m.nodes.cols() != 3 || m.triangles.cols() != 3 || (m.tets.rows() > 0 && m.tets.cols() != 4))
    fail(file, "node, triangle or tetrahedron arrays have the wrong width");
  if (!m.nodes.allFinite()) fail(file, "a node coordinate is not finite");
  check_indices(m.triangles, "triangle", n, file);
  check_indices(m.tets, "tetrahedron", n, file);
  if (m.tri_region.size() != t)
    fail(file, "region has " + std::to_string(m.tri_region.size()) + " values for " +
                   std::to_string(t) + " triangles");
  check_width(m.thickness_mm.size(), t, "thickness_mm", file);
  for (Eigen::Index e = 0; e < m.thickness_mm.size(); ++e)
    if (!(m.thickness_mm(e) >= kMinThicknessMm && m.thickness_mm(e) <= kMaxThicknessMm))
      fail(file, "thickness_mm of " + element("triangle", e) + " is " + number(m.thickness_mm(e)) +
                     ", outside " + number(kMinThicknessMm) + "-" + number(kMaxThicknessMm) +
                     " mm");
  check_width(m.fiber1.rows(), t, "fiber1", file);
  check_width(m.fiber2.rows(), t, "fiber2", file);
  check_fibers(m.fiber1, "fiber1", file);
  check_fibers(m.fiber2, "fiber2", file);
}

void check_wall_surface(const io::VolumeMesh& m, const std::string& file) {
  const mesh::SurfaceDefects defects =
      mesh::find_surface_defects(mesh::SurfaceMesh{m.nodes, m.triangles, m.tri_region});
  if (!defects.ok())
    fail(file,
         "the wall is not a closed, manifold, non-self-intersecting surface: " + defects.describe(),
         "repair it (vesica-surface) and mesh it again");
  const int components = surface_components(m);
  if (components != 1)
    fail(file, "the wall is " + std::to_string(components) + " separate closed surfaces",
         "a bladder is one surface: keep one (vesica-surface keeps the largest label component)");
}

void check_tetrahedra(const io::VolumeMesh& m, const std::string& file) {
  Eigen::Index inverted = 0, first = -1;
  for (Eigen::Index t = 0; t < m.tets.rows(); ++t) {
    const Eigen::Vector3d a = m.nodes.row(m.tets(t, 0));
    const Eigen::Vector3d b = m.nodes.row(m.tets(t, 1)), c = m.nodes.row(m.tets(t, 2)),
                          d = m.nodes.row(m.tets(t, 3));
    if (!((b - a).cross(c - a).dot(d - a) > 0.0) && inverted++ == 0) first = t;
  }
  if (inverted > 0)
    fail(file,
         std::to_string(inverted) + " of " + std::to_string(m.tets.rows()) +
             " tetrahedra are inverted or flat (the first: " + std::to_string(first) + ")",
         "mesh the urine again with vesica-mesh --fluid");
}

}  // namespace vesica::simulate::detail
