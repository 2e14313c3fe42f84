#pragma once
// The acceptance checks of a conforming cavity mesh, computed here independently of the
// library: enclosed volume by the divergence theorem (F = x/3), tetrahedron volumes by
// determinants, conformity by counting tetrahedron faces.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <map>

#include "vesica/mesh/MeshQuality.h"
#include "vesica/mesh/SurfaceMesh.h"
#include "vesica/mesh/VolumeMesh.h"

namespace vesica::test {

// Volume enclosed by the triangles: (1/3) sum over faces of centroid . area vector.
inline double divergence_volume_mm3(const Eigen::MatrixXd& points,
                                    const Eigen::MatrixXi& triangles) {
  double v = 0.0;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t) {
    const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                          c = points.row(triangles(t, 2));
    v += ((a + b + c) / 3.0).dot(0.5 * (b - a).cross(c - a)) / 3.0;
  }
  return v;
}

struct AcceptanceNumbers {
  double relative_volume_error = 1.0;
  long inverted = 0;
  long wall_triangles_not_single_face = 0;
  double min_dihedral_deg = 0.0;
  double fraction_radius_ratio_ge_0_3 = 0.0;
};

inline AcceptanceNumbers acceptance_numbers(const mesh::VolumeMesh& m) {
  AcceptanceNumbers n;
  double tet_volume = 0.0;
  std::map<std::array<int, 3>, int> face_uses;
  long good = 0;
  n.min_dihedral_deg = 180.0;
  for (Eigen::Index t = 0; t < m.tets.rows(); ++t) {
    const Eigen::Vector3d a = m.nodes.row(m.tets(t, 0)), b = m.nodes.row(m.tets(t, 1)),
                          c = m.nodes.row(m.tets(t, 2)), d = m.nodes.row(m.tets(t, 3));
    Eigen::Matrix3d j;
    j << b - a, c - a, d - a;
    const double v = j.determinant() / 6.0;
    tet_volume += v;
    if (v <= 0) ++n.inverted;
    const mesh::TetShape s = mesh::tet_shape(a, b, c, d);
    n.min_dihedral_deg = std::min(n.min_dihedral_deg, s.min_dihedral_deg);
    if (s.radius_ratio >= 0.3) ++good;
    for (int skip = 0; skip < 4; ++skip) {
      std::array<int, 3> f{};
      for (int k = 0, i = 0; k < 4; ++k)
        if (k != skip) f[i++] = m.tets(t, k);
      std::sort(f.begin(), f.end());
      ++face_uses[f];
    }
  }
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) {
    std::array<int, 3> f{m.triangles(t, 0), m.triangles(t, 1), m.triangles(t, 2)};
    std::sort(f.begin(), f.end());
    const auto it = face_uses.find(f);
    if (it == face_uses.end() || it->second != 1) ++n.wall_triangles_not_single_face;
  }
  const double surface_volume = divergence_volume_mm3(m.nodes, m.triangles);
  n.relative_volume_error = std::abs(tet_volume - surface_volume) / surface_volume;
  n.fraction_radius_ratio_ge_0_3 = m.tets.rows() ? static_cast<double>(good) / m.tets.rows() : 0.0;
  return n;
}

inline void expect_acceptance(const mesh::VolumeMesh& m) {
  const AcceptanceNumbers n = acceptance_numbers(m);
  EXPECT_GT(m.tets.rows(), 0);
  EXPECT_LT(n.relative_volume_error, 1e-9);
  EXPECT_EQ(n.inverted, 0);
  EXPECT_EQ(n.wall_triangles_not_single_face, 0);
  EXPECT_GE(n.min_dihedral_deg, 5.0);
  EXPECT_GE(n.fraction_radius_ratio_ge_0_3, 0.99);
  std::printf("tets %ld triangles %ld: volume error %.3g, min dihedral %.2f deg, rr>=0.3 %.4f\n",
              static_cast<long>(m.tets.rows()), static_cast<long>(m.triangles.rows()),
              n.relative_volume_error, n.min_dihedral_deg, n.fraction_radius_ratio_ge_0_3);
}

}  // namespace vesica::test
