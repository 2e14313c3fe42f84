// Neobladders built from an ileal segment: each configuration's surface keeps the tissue
// it is made of (area = L x C, the surgeon's bowel) and joins the urethra at its lowest
// point; their volumes follow Hinman's geometry (a tube holds least, a sphere most).
#include <gtest/gtest.h>

#include <cmath>

#include "SurfaceTestSupport.h"
#include "TestData.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/surface/PolygonMeshProcessing.h"
#include "vesica/surface/Shapes.h"

namespace vesica::test {
namespace {

using surface::ShapeKind;
using surface::ShapeSpec;
using surface::TriangleSurface;

struct IlealCase {
  const char* name;
  ShapeKind kind;
  double length_cm;
  double afferent_cm;
};

ShapeSpec ileal_spec(const IlealCase& c) {
  ShapeSpec spec;
  spec.kind = c.kind;
  spec.ileum.length_cm = c.length_cm;
  spec.ileum.afferent_limb_cm = c.afferent_cm;
  spec.edge_mm = 6.0;
  return spec;
}

TriangleSurface built(const IlealCase& c) {
  surface::SurfaceStageOptions options;
  options.shape = ileal_spec(c);
  options.output = (scratch_dir(std::string("ileal-") + c.name) / "s.vtp").string();
  return run_stage(options);
}

class IlealPouch : public ::testing::TestWithParam<IlealCase> {};

TEST_P(IlealPouch, KeepsTheTissueAreaOfTheSegmentAndJoinsTheUrethraAtTheBottom) {
  const IlealCase c = GetParam();
  const TriangleSurface s = built(c);
  const double tissue_mm2 = c.length_cm * 10.0 * 80.0;  // L x C, C = 8 cm by default
  const double area = surface::surface_area(s.V, s.F);
  std::printf("[ ileal ] %s L %g cm: area %.1f cm² (L x C %.1f), volume %.1f ml, %d triangles\n",
              c.name, c.length_cm, area / 100, tissue_mm2 / 100,
              surface::enclosed_volume(s.V, s.F) / 1e3, static_cast<int>(s.F.rows()));
  EXPECT_NEAR(area / tissue_mm2, 1.0, 0.02);
  EXPECT_TRUE(surface::check_surface(s).passed()) << surface::check_surface(s).first_failure();
  const OutletPatch outlet = outlet_patch(s);
  EXPECT_GT(outlet.triangles, 0);
  EXPECT_LT(outlet.max_height_mm, 6.0);
}

INSTANTIATE_TEST_SUITE_P(IlealShapes, IlealPouch,
                         ::testing::Values(IlealCase{"tubular40", ShapeKind::Tubular, 40, 0},
                                           IlealCase{"tubular60", ShapeKind::Tubular, 60, 0},
                                           IlealCase{"studer40", ShapeKind::Studer, 40, 0},
                                           IlealCase{"studer56_afferent14", ShapeKind::Studer, 56,
                                                     14},
                                           IlealCase{"hautmann60", ShapeKind::Hautmann, 60, 0},
                                           IlealCase{"sphere40", ShapeKind::Sphere, 40, 0}),
                         [](const auto& info) { return std::string(info.param.name); });

// Hinman's geometry: the same 40 cm of bowel encloses least as a tube (V = π r² length,
// r = C/2π) and most as a sphere (V = A^1.5 / (6 √π)).
TEST(IlealShapes, DetubularizingTheSameBowelEnclosesMoreAsHinmanComputed) {
  const double area = 400.0 * 80.0, r = 80.0 / (2 * M_PI);
  const double tube_ml = (M_PI * r * r * (400 - 2 * r) + 4.0 / 3 * M_PI * r * r * r) / 1e3;
  const double sphere_ml = std::pow(area, 1.5) / (6 * std::sqrt(M_PI)) / 1e3;
  const auto volume = [](const IlealCase& c) {
    const TriangleSurface s = built(c);
    return surface::enclosed_volume(s.V, s.F) / 1e3;
  };
  const double tube = volume({"hinman_tube", ShapeKind::Tubular, 40, 0});
  const double studer = volume({"hinman_studer", ShapeKind::Studer, 40, 0});
  const double hautmann = volume({"hinman_hautmann", ShapeKind::Hautmann, 40, 0});
  const double sphere = volume({"hinman_sphere", ShapeKind::Sphere, 40, 0});
  // The tube's 6 mm edges cut its 80 mm circumference in about 13 chords: 2-3 % less volume.
  EXPECT_NEAR(tube / tube_ml, 1.0, 0.04);
  EXPECT_NEAR(sphere / sphere_ml, 1.0, 0.03);
  EXPECT_LT(tube, studer);
  EXPECT_LT(studer, hautmann);
  EXPECT_LT(hautmann, sphere);
}

TEST(IlealShapes, ASegmentTooShortForItsTubeIsRefused) {
  ShapeSpec spec = ileal_spec({"short", ShapeKind::Studer, 40, 21});
  EXPECT_THROW(surface::make_shape(spec), Error);
  spec = ileal_spec({"limb_on_w", ShapeKind::Hautmann, 60, 12});
  EXPECT_THROW(surface::make_shape(spec), Error);
  spec = ileal_spec({"no_length", ShapeKind::Tubular, 0, 0});
  EXPECT_THROW(surface::make_shape(spec), Error);
  spec = ileal_spec({"coarse", ShapeKind::Tubular, 40, 0});
  spec.edge_mm = 8;  // more than half the bowel's 12.7 mm radius: the remesher opens holes
  EXPECT_THROW(surface::make_shape(spec), Error);
}

}  // namespace
}  // namespace vesica::test
