// Quality measures against hand-computed values of known elements.
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/mesh/MeshQuality.h"

using namespace vesica::mesh;

TEST(MeshQuality, RegularTetrahedron) {
  // Alternate corners of a cube: a regular tetrahedron with edge sqrt(8).
  const TetShape s = tet_shape({1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1});
  EXPECT_NEAR(std::abs(s.volume_mm3), 8.0 / 3.0, 1e-12);
  EXPECT_NEAR(s.radius_ratio, 1.0, 1e-12);
  const double dihedral = std::acos(1.0 / 3.0) * 180.0 / M_PI;  // 70.5288 deg
  EXPECT_NEAR(s.min_dihedral_deg, dihedral, 1e-9);
  EXPECT_NEAR(s.max_dihedral_deg, dihedral, 1e-9);
}

TEST(MeshQuality, TrirectangularCorner) {
  // Corner tet (0, e1, e2, e3): V = 1/6, three 90 deg dihedrals, three of acos(1/sqrt 3).
  const TetShape s = tet_shape({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  EXPECT_NEAR(s.volume_mm3, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(s.max_dihedral_deg, 90.0, 1e-9);
  EXPECT_NEAR(s.min_dihedral_deg, std::acos(1.0 / std::sqrt(3.0)) * 180.0 / M_PI, 1e-9);
  // r_in = 3V/A = 0.5 / (1.5 + sqrt(3)/2); R = sqrt(3)/2.
  const double r_in = 0.5 / (1.5 + std::sqrt(3.0) / 2.0);
  EXPECT_NEAR(s.radius_ratio, 3.0 * r_in / (std::sqrt(3.0) / 2.0), 1e-12);
}

TEST(MeshQuality, InvertedTetrahedronHasNegativeVolume) {
  EXPECT_LT(tet_shape({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}).volume_mm3, 0.0);
}

TEST(MeshQuality, TriangleAngles) {
  EXPECT_NEAR(triangle_min_angle_deg({0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}), 60.0,
              1e-9);
  EXPECT_NEAR(triangle_min_angle_deg({0, 0, 0}, {std::sqrt(3.0), 0, 0}, {0, 1, 0}), 30.0, 1e-9);
}
