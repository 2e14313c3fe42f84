// Defects of bad surfaces are found and counted: a hole, a duplicated triangle, two
// interpenetrating spheres.
#include <gtest/gtest.h>

#include "TestSurfaces.h"
#include "vesica/core/Error.h"
#include "vesica/mesh/SurfaceDefects.h"

using namespace vesica;
using namespace vesica::mesh;

namespace {

SurfaceMesh without_first_triangle(SurfaceMesh s) {
  s.triangles = s.triangles.bottomRows(s.triangles.rows() - 1).eval();
  s.region = s.region.tail(s.region.size() - 1).eval();
  return s;
}

// Two copies of a sphere, the second shifted by half a radius: closed and manifold, but
// the two shells cross each other.
SurfaceMesh interpenetrating_spheres() {
  const SurfaceMesh a = test::icosphere(10.0, 2);
  SurfaceMesh s;
  s.points.resize(2 * a.points.rows(), 3);
  s.points << a.points, a.points.rowwise() + Eigen::RowVector3d(5.0, 0, 0);
  s.triangles.resize(2 * a.triangles.rows(), 3);
  s.triangles << a.triangles, a.triangles.array() + static_cast<int>(a.points.rows());
  s.region = Eigen::VectorXi::Constant(s.triangles.rows(), 1);
  return s;
}

}  // namespace

TEST(SurfaceDefects, ClosedSphereHasNone) {
  const SurfaceDefects d = find_surface_defects(test::icosphere(10.0, 2));
  EXPECT_TRUE(d.ok()) << d.describe();
  EXPECT_TRUE(d.self_intersections_checked);
}

TEST(SurfaceDefects, HoleGivesThreeBoundaryEdges) {
  const SurfaceDefects d = find_surface_defects(without_first_triangle(test::icosphere(10.0, 2)));
  EXPECT_EQ(d.boundary_edges, 3u);
  EXPECT_EQ(d.nonmanifold_edges, 0u);
  EXPECT_FALSE(d.ok());
}

TEST(SurfaceDefects, DuplicatedTriangleGivesThreeNonManifoldEdges) {
  SurfaceMesh s = test::icosphere(10.0, 2);
  s.triangles.conservativeResize(s.triangles.rows() + 1, 3);
  s.triangles.row(s.triangles.rows() - 1) = s.triangles.row(0);
  s.region.conservativeResize(s.region.size() + 1);
  s.region(s.region.size() - 1) = 1;
  const SurfaceDefects d = find_surface_defects(s);
  EXPECT_EQ(d.nonmanifold_edges, 3u);
  EXPECT_FALSE(d.self_intersections_checked);
}

TEST(SurfaceDefects, InterpenetratingSpheresSelfIntersect) {
  const SurfaceDefects d = find_surface_defects(interpenetrating_spheres());
  EXPECT_EQ(d.boundary_edges, 0u);
  EXPECT_EQ(d.nonmanifold_edges, 0u);
  EXPECT_GT(d.self_intersecting_pairs, 0u);
  try {
    require_valid_surface(interpenetrating_spheres(), "two.vtp");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "two.vtp");
    EXPECT_NE(std::string(e.what()).find("self-intersecting triangle pairs"), std::string::npos)
        << e.what();
  }
}
