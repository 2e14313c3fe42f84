// The urine mesh of a sphere: conforming tetrahedra whose total volume is the volume
// enclosed by the wall triangles, with good shapes; and a gmsh failure becomes an error.
#include <gtest/gtest.h>

#include "MeshAcceptance.h"
#include "TestSurfaces.h"
#include "vesica/core/Error.h"
#include "vesica/mesh/BladderMesh.h"

using namespace vesica;
using namespace vesica::mesh;

TEST(SphereCavity, ConformsFillsAndHasGoodShapes) {
  SurfaceMesh sphere = test::icosphere(40.0, 4);  // 5120 triangles, edge ~3.4 mm
  // An outlet cap keeps its own tag through the mesher.
  for (Eigen::Index t = 0; t < sphere.triangles.rows(); ++t)
    if (sphere.points(sphere.triangles(t, 0), 2) > 36.0)
      sphere.region(t) = static_cast<int>(Region::Outlet);
  const VolumeMesh m = build_bladder_mesh(sphere, MembraneOptions{}, CavityOptions{}, "sphere");
  test::expect_acceptance(m);
  // Wall nodes and triangles are the surface's, unchanged.
  EXPECT_EQ(m.nodes.topRows(sphere.points.rows()), sphere.points);
  EXPECT_EQ(m.triangles, sphere.triangles);
  EXPECT_EQ(m.tri_region, sphere.region);
}

TEST(SphereCavity, InwardSurfaceIsTurnedOutward) {
  SurfaceMesh sphere = test::icosphere(20.0, 2);
  flip_orientation(sphere);
  const VolumeMesh m = build_bladder_mesh(sphere, MembraneOptions{}, CavityOptions{}, "sphere");
  EXPECT_GT(test::divergence_volume_mm3(m.nodes, m.triangles), 0.0);
  test::expect_acceptance(m);
}

TEST(SphereCavity, GradingCoarsensTheInterior) {
  const SurfaceMesh sphere = test::icosphere(40.0, 4);
  const VolumeMesh uniform =
      build_bladder_mesh(sphere, MembraneOptions{}, CavityOptions{}, "sphere");
  CavityOptions graded;
  graded.max_size_mm = 10.0;
  const VolumeMesh coarse = build_bladder_mesh(sphere, MembraneOptions{}, graded, "sphere");
  EXPECT_LT(coarse.tets.rows(), uniform.tets.rows() / 2);
  test::expect_acceptance(coarse);
}

TEST(SphereCavity, GmshFailureIsAnErrorNotACrash) {
  // Two interpenetrating shells, given to the mesher without the surface check.
  const SurfaceMesh a = test::icosphere(10.0, 2);
  SurfaceMesh s;
  s.points.resize(2 * a.points.rows(), 3);
  s.points << a.points, a.points.rowwise() + Eigen::RowVector3d(5.0, 0, 0);
  s.triangles.resize(2 * a.triangles.rows(), 3);
  s.triangles << a.triangles, a.triangles.array() + static_cast<int>(a.points.rows());
  s.region = Eigen::VectorXi::Constant(s.triangles.rows(), 1);
  try {
    mesh_cavity(s, CavityOptions{}, "two.vtp");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.file(), "two.vtp");
    EXPECT_NE(std::string(e.what()).find("gmsh"), std::string::npos) << e.what();
  }
}
