// The urine's section through the outlet axis, on a box of tetrahedra whose velocity is
// known everywhere (u = (0, 0, k z)): the plane is the one the outlet's axis defines, the
// section is the whole 20 x 20 mm square, and the speed at every corner is k |z|.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <Eigen/Geometry>

#include "CompareTestSupport.h"
#include "vesica/compare/report/UrineSection.h"
#include "vesica/core/Error.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

double polygon_area(const vesica::compare::UrineSection& s, const std::vector<int>& polygon) {
  Eigen::Vector3d twice = Eigen::Vector3d::Zero();
  const Eigen::Vector3d& a = s.points_mm[static_cast<std::size_t>(polygon[0])];
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k)
    twice += (s.points_mm[static_cast<std::size_t>(polygon[k])] - a)
                 .cross(s.points_mm[static_cast<std::size_t>(polygon[k + 1])] - a);
  return 0.5 * twice.norm();
}

}  // namespace

TEST(UrineSection, CutsTheUrineOnThePlaneOfTheOutletAxisWithItsSpeed) {
  const fs::path vtu = scratch_dir("urine-section") / "fluid_0001.vtu";
  write_fluid_box(vtu, 40.0);  // 1/s: 0.4 m/s at z = ±10 mm
  const vesica::compare::UrineSection s = vesica::compare::urine_section(vtu);
  EXPECT_NEAR(s.normal.x(), 1.0, 1e-12);  // the axis is +z: the plane is sagittal
  EXPECT_NEAR(s.along.z(), 1.0, 1e-12);
  EXPECT_NEAR(s.max_speed_m_s, 0.4, 1e-12);
  ASSERT_FALSE(s.polygons.empty());
  ASSERT_EQ(s.points_mm.size(), s.speed_m_s.size());
  double highest = 0.0;
  for (std::size_t i = 0; i < s.points_mm.size(); ++i) {
    EXPECT_NEAR(s.points_mm[i].x(), 0.3, 1e-9);
    EXPECT_NEAR(s.speed_m_s[i], 1e-3 * 40.0 * std::abs(s.points_mm[i].z()), 1e-12);
    highest = std::max(highest, s.speed_m_s[i]);
  }
  EXPECT_NEAR(highest, 0.4, 1e-12);  // the square's top and bottom edges
  double area = 0.0;
  for (const std::vector<int>& polygon : s.polygons) {
    EXPECT_GE(polygon.size(), 3u);
    EXPECT_LE(polygon.size(), 4u);  // a plane cuts a tet in a triangle or a quad
    area += polygon_area(s, polygon);
  }
  EXPECT_NEAR(area, 400.0, 1e-6);  // mm²: the box's whole cross-section
}

TEST(UrineSection, AFrameWithoutTheOutletIsRefusedByName) {
  const fs::path dir = scratch_dir("urine-section-bad");
  std::ofstream(dir / "wall.vtu") << "<VTKFile type=\"UnstructuredGrid\"></VTKFile>\n";
  try {
    vesica::compare::urine_section(dir / "wall.vtu");
    FAIL() << "a frame without tetrahedra was cut";
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find("wall.vtu"), std::string::npos) << e.what();
  }
}
