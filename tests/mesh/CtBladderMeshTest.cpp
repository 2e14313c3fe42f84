// The real CT bladder (reference label of the abdomen CT): acceptance of the urine mesh
// and the thesis-scale meshes (about 2,300 wall triangles / 21,000 tetrahedra for the
// cystometry model, 17,000 / 73,000 for the neobladder model), within +-25 %.
#include <gtest/gtest.h>

#include "MeshAcceptance.h"
#include "TestData.h"
#include "TestSurfaces.h"
#include "vesica/mesh/BladderMesh.h"

using namespace vesica;
using namespace vesica::mesh;

namespace {
const char* kLabel = "data/ct/abdomen-3mm/bladder-reference.nii.gz";

void expect_within_25_percent(double value, double target) {
  EXPECT_GE(value, 0.75 * target);
  EXPECT_LE(value, 1.25 * target);
}
}  // namespace

TEST(CtBladderMesh, CystometryScale) {
  VESICA_REQUIRE_SHARED(label, kLabel);
  const SurfaceMesh surface = test::ct_bladder_surface(label, 2300);
  CavityOptions options;
  options.max_size_mm = 4.5;  // a little finer inside than the wall, as in the thesis
  const VolumeMesh m = build_bladder_mesh(surface, MembraneOptions{}, options, label.string());
  test::expect_acceptance(m);
  expect_within_25_percent(m.triangles.rows(), 2300);
  expect_within_25_percent(m.tets.rows(), 21000);
}

TEST(CtBladderMesh, NeobladderScale) {
  VESICA_REQUIRE_SHARED(label, kLabel);
  const SurfaceMesh surface = test::ct_bladder_surface(label, 17000);
  CavityOptions options;
  options.max_size_mm = 4.0;  // graded: wall edges ~1.8 mm, 4 mm inside
  const VolumeMesh m = build_bladder_mesh(surface, MembraneOptions{}, options, label.string());
  test::expect_acceptance(m);
  expect_within_25_percent(m.triangles.rows(), 17000);
  expect_within_25_percent(m.tets.rows(), 73000);
}
