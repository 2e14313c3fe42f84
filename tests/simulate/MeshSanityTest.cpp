// simulate refuses a mesh that is not one bladder wall instead of "simulating" it: two
// cavities, a wall through itself, arrays of the wrong width, non-finite or absurd values,
// inverted urine tetrahedra. Each file is refused with one line naming it and the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../io/OctahedronMesh.h"
#include "TestData.h"
#include "vesica/core/Error.h"
#include "vesica/io/VtuFile.h"
#include "vesica/simulate/wall/MeshReader.h"

namespace fs = std::filesystem;
using vesica::io::VolumeMesh;

namespace {

// The reader's error for `mesh` written as a .vtu, or "" when it was accepted.
std::string refusal(const VolumeMesh& mesh, const std::string& name, bool urine = false) {
  // A folder per case: ctest runs the cases side by side, and scratch_dir empties it.
  const fs::path file = vesica::test::scratch_dir("simulate-sanity-" + name) / (name + ".vtu");
  vesica::io::write_mesh_vtu(mesh, file);
  try {
    if (urine)
      vesica::simulate::read_urine(file);
    else
      vesica::simulate::read_wall(file, 3e-3);
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find(file.string()), std::string::npos) << e.what();
    return e.what();
  }
  return "";
}

bool says(const std::string& error, const std::string& part) {
  return error.find(part) != std::string::npos;
}

}  // namespace

TEST(MeshSanity, TheOctahedronIsAcceptedAsWallAndUrine) {
  EXPECT_EQ(refusal(vesica::test::octahedron_mesh(), "ok"), "");
  EXPECT_EQ(refusal(vesica::test::octahedron_mesh(), "ok-urine", true), "");
}

TEST(MeshSanity, TwoSeparateCavitiesAreRefused) {
  const VolumeMesh one = vesica::test::octahedron_mesh();
  VolumeMesh two = one;
  const Eigen::Index n = one.nodes.rows(), m = one.triangles.rows();
  two.nodes.conservativeResize(2 * n, 3);
  two.nodes.bottomRows(n) = one.nodes.rowwise() + Eigen::RowVector3d(50, 0, 0);
  two.triangles.conservativeResize(2 * m, 3);
  two.triangles.bottomRows(m) = one.triangles.array() + static_cast<int>(n);
  two.tri_region.conservativeResize(2 * m);
  two.tri_region.tail(m) = one.tri_region;
  two.thickness_mm.conservativeResize(2 * m);
  two.thickness_mm.tail(m) = one.thickness_mm;
  two.fiber1.conservativeResize(2 * m, 3);
  two.fiber1.bottomRows(m) = one.fiber1;
  two.fiber2.conservativeResize(2 * m, 3);
  two.fiber2.bottomRows(m) = one.fiber2;
  two.tets.resize(0, 4);
  EXPECT_TRUE(says(refusal(two, "two-cavities"), "2 separate closed surfaces"));
}

TEST(MeshSanity, AWallThroughItselfIsRefused) {
  VolumeMesh m = vesica::test::octahedron_mesh();
  m.nodes.row(4) << 0, 0, -15;  // the top vertex pushed through the bottom
  m.tets.resize(0, 4);
  const std::string error = refusal(m, "self-intersecting");
  EXPECT_TRUE(says(error, "self-intersecting")) << error;
}

TEST(MeshSanity, AbsurdThicknessIsRefused) {
  VolumeMesh m = vesica::test::octahedron_mesh();
  m.thickness_mm(3) = 1e30;
  EXPECT_TRUE(says(refusal(m, "thick"), "thickness_mm of triangle 3 is 1e+30, outside 0.1-30 mm"));
  m.thickness_mm(3) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(says(refusal(m, "nan-thick"), "thickness_mm of triangle 3"));
}

TEST(MeshSanity, FibersThatAreNotFiniteUnitVectorsAreRefused) {
  VolumeMesh m = vesica::test::octahedron_mesh();
  m.fiber1(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_TRUE(says(refusal(m, "nan-fiber"), "fiber1 of triangle 2 is not a finite unit vector"));
}

TEST(MeshSanity, FiberArraysOfTheWrongWidthAreRefused) {
  const VolumeMesh m = vesica::test::octahedron_mesh();
  const fs::path file = vesica::test::scratch_dir("simulate-sanity-width") / "wide.vtu";
  vesica::io::write_mesh_vtu(m, file);
  vesica::io::VtuGrid g = vesica::io::read_vtu(file);
  for (auto& a : g.cell_data)
    if (a.name == "fiber1") {  // the same numbers as two components
      a.components = 2;
      a.values.resize(a.values.size() / 3 * 2);
    }
  vesica::io::write_vtu(g, file);
  try {
    vesica::simulate::read_wall(file, 3e-3);
    FAIL() << "a two-component fiber1 was accepted";
  } catch (const vesica::Error& e) {
    EXPECT_TRUE(says(e.what(), "cell array fiber1 has 2 components, expected 3")) << e.what();
  }
}

TEST(MeshSanity, InvertedUrineTetrahedraAreRefused) {
  VolumeMesh m = vesica::test::octahedron_mesh();
  for (Eigen::Index t = 0; t < m.tets.rows(); t += 4) std::swap(m.tets(t, 1), m.tets(t, 2));
  EXPECT_TRUE(says(refusal(m, "inverted", true), "2 of 8 tetrahedra are inverted or flat"));
}
