// Fiber frames and thickness of membrane elements against their definition: unit,
// in-plane, perpendicular, family 1 along the projected direction.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "TestSurfaces.h"
#include "vesica/mesh/MembraneFields.h"

using namespace vesica;
using namespace vesica::mesh;

TEST(MembraneFields, FramesAreUnitInPlaneAndPerpendicular) {
  SurfaceMesh s = test::icosphere(40.0, 3);
  s.region(0) = static_cast<int>(Region::Fixed);
  MembraneOptions options;
  options.thickness_by_region_mm[Region::Fixed] = 4.5;
  options.fiber_direction = Eigen::Vector3d(0, 0, 2);
  const MembraneFields f = membrane_fields(s, options);
  EXPECT_DOUBLE_EQ(f.thickness_mm(0), 4.5);
  EXPECT_DOUBLE_EQ(f.thickness_mm(1), 3.0);
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    const Eigen::Vector3d a = s.points.row(s.triangles(t, 0)), b = s.points.row(s.triangles(t, 1)),
                          c = s.points.row(s.triangles(t, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    const Eigen::Vector3d f1 = f.fiber1.row(t), f2 = f.fiber2.row(t);
    EXPECT_NEAR(f1.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f2.norm(), 1.0, 1e-12);
    EXPECT_NEAR(f1.dot(n), 0.0, 1e-12);
    EXPECT_NEAR(f2.dot(n), 0.0, 1e-12);
    EXPECT_NEAR(f1.dot(f2), 0.0, 1e-12);
    EXPECT_NEAR(f1.cross(f2).dot(n), 1.0, 1e-12);  // right-handed with the outward normal
    // Family 1 is the normalized projection of z on the plane (when it is not normal).
    const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d projected = z - z.dot(n) * n;
    if (projected.norm() > 1e-2) {
      EXPECT_NEAR(f1.dot(projected.normalized()), 1.0, 1e-12);
    }
  }
}

TEST(MembraneFields, DirectionNormalToTriangleFallsBackToEdge) {
  SurfaceMesh s;
  s.points.resize(3, 3);
  s.points << 0, 0, 0, 1, 0, 0, 0, 1, 0;
  s.triangles.resize(1, 3);
  s.triangles << 0, 1, 2;
  s.region = Eigen::VectorXi::Constant(1, 1);
  const MembraneFields f = membrane_fields(s, MembraneOptions{});  // z is the normal here
  EXPECT_NEAR((f.fiber1.row(0) - Eigen::RowVector3d(1, 0, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((f.fiber2.row(0) - Eigen::RowVector3d(0, 1, 0)).norm(), 0.0, 1e-12);
}

TEST(MembraneFields, LongAxisOfAnEllipsoidIsItsLongestSemiAxis) {
  SurfaceMesh s = test::icosphere(1.0, 3);
  s.points = s.points * Eigen::Vector3d(50.0, 20.0, 30.0).asDiagonal();
  s.points.rowwise() += Eigen::RowVector3d(-10.0, 200.0, 35.0);  // anywhere in the body
  EXPECT_NEAR(std::abs(long_axis(s).x()), 1.0, 1e-9);
  s.points = test::icosphere(1.0, 3).points * Eigen::Vector3d(20.0, 30.0, 50.0).asDiagonal();
  EXPECT_NEAR(std::abs(long_axis(s).z()), 1.0, 1e-9);
}
