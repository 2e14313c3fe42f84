// What-if shapes at an exact volume, principal-axis morphing at constant volume, and the
// region tags, against analytic geometry (sphere caps, great circles, axis ratios).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "SurfaceTestSupport.h"
#include "TestData.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/surface/Morph.h"
#include "vesica/surface/PolygonMeshProcessing.h"
#include "vesica/surface/Shapes.h"
#include "vesica/surface/SurfaceRegions.h"

namespace vesica::test {
namespace {

using surface::ShapeKind;
using surface::ShapeSpec;
using surface::TriangleSurface;

Eigen::Vector3d extent(const TriangleSurface& s) {
  return (s.V.colwise().maxCoeff() - s.V.colwise().minCoeff()).transpose();
}

struct ShapeCase {
  const char* name;
  ShapeKind kind;
  double elongation;
};

class WhatIfShape : public ::testing::TestWithParam<ShapeCase> {};

TEST_P(WhatIfShape, ExactVolumeCheckedAndOutletAtTheBottom) {
  const ShapeCase c = GetParam();
  surface::SurfaceStageOptions options;
  ShapeSpec spec;
  spec.kind = c.kind;
  spec.volume_ml = 320;
  spec.elongation = c.elongation;
  options.shape = spec;
  options.output = (scratch_dir(std::string("surface-shape-") + c.name) / "s.vtp").string();
  nlohmann::json summary;
  const TriangleSurface s = run_stage(options, &summary);

  EXPECT_NEAR(surface::enclosed_volume(s.V, s.F) / 320e3, 1.0, 1e-12);
  EXPECT_TRUE(surface::check_surface(s).passed()) << surface::check_surface(s).first_failure();
  const Eigen::VectorXd angles = surface::triangle_min_angles_deg(s.V, s.F);
  EXPECT_GE((angles.array() >= 25.0).cast<double>().mean(), 0.99);
  // Outlet: a patch around the lowest point (LPS: smallest z).
  const OutletPatch outlet = outlet_patch(s);
  EXPECT_GT(outlet.triangles, 0);
  EXPECT_LT(outlet.max_height_mm, 15.0);
  if (c.kind == ShapeKind::Ellipsoid) {  // (r, r, e r): z extent over x extent
    EXPECT_NEAR(extent(s).z() / extent(s).x(), c.elongation, 0.03 * c.elongation);
  }
  if (c.kind == ShapeKind::Pouch) {  // reservoir elongated left-right, neck below
    EXPECT_NEAR(extent(s).x() / extent(s).y(), c.elongation, 0.05 * c.elongation);
    EXPECT_GT(extent(s).z(), extent(s).y() * 1.1) << "the neck adds height below the reservoir";
  }
}

INSTANTIATE_TEST_SUITE_P(SurfaceShapes, WhatIfShape,
                         ::testing::Values(ShapeCase{"sphere", ShapeKind::Sphere, 1.0},
                                           ShapeCase{"ellipsoid", ShapeKind::Ellipsoid, 1.6},
                                           ShapeCase{"pouch_spherical", ShapeKind::Pouch, 1.0},
                                           ShapeCase{"pouch_elongated", ShapeKind::Pouch, 2.0}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(SurfaceShapes, EllipsoidBySemiAxesKeepsProportions) {
  ShapeSpec spec;
  spec.kind = ShapeKind::Ellipsoid;
  spec.volume_ml = 200;
  spec.semi_axes_mm = Eigen::Vector3d(50, 40, 30);
  const TriangleSurface s = surface::make_shape(spec);
  const double k = std::cbrt(200e3 / (4.0 / 3.0 * M_PI * 50 * 40 * 30));  // analytic scale
  const Eigen::Vector3d expected = 2 * k * Eigen::Vector3d(50, 40, 30);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(extent(s)(d) / expected(d), 1.0, 0.02);
}

TEST(SurfaceMorph, StretchesPrincipalAxesAtConstantVolume) {
  ShapeSpec spec;
  spec.kind = ShapeKind::Ellipsoid;
  spec.volume_ml = 250;
  spec.semi_axes_mm = Eigen::Vector3d(30, 45, 36);  // longest along y
  TriangleSurface s = surface::make_shape(spec);
  const Eigen::Vector3d before = extent(s);
  surface::morph_principal_axes(Eigen::Vector3d(1.5, 1.0, 1.0), s);
  EXPECT_NEAR(surface::enclosed_volume(s.V, s.F) / 250e3, 1.0, 1e-12);
  const double n = std::cbrt(1.5);  // stretches normalised to a unit product
  EXPECT_NEAR(extent(s).y() / before.y(), 1.5 / n, 0.02);
  EXPECT_NEAR(extent(s).x() / before.x(), 1.0 / n, 0.02);
  EXPECT_NEAR(extent(s).z() / before.z(), 1.0 / n, 0.02);
}

TriangleSurface sphere(double radius_mm, double edge_mm) {
  ShapeSpec spec;
  spec.volume_ml = 4.0 / 3.0 * M_PI * std::pow(radius_mm, 3) * 1e-3;
  spec.edge_mm = edge_mm;
  return surface::make_shape(spec);
}

TEST(SurfaceRegions, EdgePathsFollowGreatCircles) {
  const double R = 40;
  const TriangleSurface s = sphere(R, 3);
  const Eigen::VectorXd d = surface::edge_path_distances(s.V, s.F, 0);
  const Eigen::Vector3d a = s.V.row(0).normalized();
  for (Eigen::Index v = 0; v < s.V.rows(); ++v) {
    const double great_circle =
        R * std::acos(std::clamp(a.dot(s.V.row(v).normalized()), -1.0, 1.0));
    // Edge paths zig-zag: never shorter than the geodesic, at most ~15% longer.
    EXPECT_GE(d(v), great_circle - 0.5);
    EXPECT_LE(d(v), 1.15 * great_circle + 3.0);
  }
}

double tagged_area(const TriangleSurface& s, Region r) {
  double area = 0;
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
    if (s.region(f) == static_cast<int>(r)) {
      const Eigen::Vector3d a = s.V.row(s.F(f, 0)), b = s.V.row(s.F(f, 1)), c = s.V.row(s.F(f, 2));
      area += 0.5 * (b - a).cross(c - a).norm();
    }
  return area;
}

TEST(SurfaceRegions, PatchesMatchSphericalCaps) {
  const double R = 40;
  TriangleSurface s = sphere(R, 3);
  surface::RegionOptions options;
  options.outlet_radius_mm = 8;
  options.fixed_radius_mm = 25;
  options.inlets = {Eigen::Vector3d(0, R, 0), Eigen::Vector3d(0, -R, 0)};
  options.inlet_radius_mm = 6;
  options.support_below_mm = 0;
  const surface::RegionSummary summary = surface::assign_regions(options, s);
  const auto cap = [R](double r) { return 2 * M_PI * R * R * (1 - std::cos(r / R)); };
  EXPECT_NEAR(summary.outlet_mm.z(), -R, 0.5);  // auto outlet: the most inferior point
  EXPECT_NEAR(tagged_area(s, Region::Outlet) / cap(8), 1.0, 0.25);
  EXPECT_NEAR((tagged_area(s, Region::Outlet) + tagged_area(s, Region::Fixed)) / cap(25), 1.0,
              0.15);
  EXPECT_NEAR(tagged_area(s, Region::Inlet) / (2 * cap(6)), 1.0, 0.3);
  EXPECT_NEAR(surface::surface_area(s.V, s.F) - tagged_area(s, Region::Wall) -
                  tagged_area(s, Region::Outlet) - tagged_area(s, Region::Fixed) -
                  tagged_area(s, Region::Inlet),
              0.0, 1e-6);
}

TEST(SurfaceRegions, HeightBandsAndLandmarkOutlet) {
  const double R = 40;
  TriangleSurface s = sphere(R, 3);
  surface::RegionOptions options;
  options.outlet = Eigen::Vector3d(R, 0, 0);  // a landmark on the left side
  options.fixed_below_mm = 10;
  options.support_below_mm = 30;
  const surface::RegionSummary summary = surface::assign_regions(options, s);
  EXPECT_NEAR((summary.outlet_mm - Eigen::Vector3d(R, 0, 0)).norm(), 0.0, 3.0);
  // Bands measured from the outlet's height (z = 0): zone areas of a sphere, 2 pi R h.
  const double fixed_band = 2 * M_PI * R * (R + 10), support_band = 2 * M_PI * R * 20;
  EXPECT_NEAR((tagged_area(s, Region::Fixed) + tagged_area(s, Region::Outlet)) / fixed_band, 1.0,
              0.05);
  EXPECT_NEAR(tagged_area(s, Region::Support) / support_band, 1.0, 0.08);
}

TEST(SurfaceRegions, FarLandmarkIsAUsageError) {
  TriangleSurface s = sphere(40, 6);
  surface::RegionOptions options;
  options.inlets = {Eigen::Vector3d(0, 0, 200)};
  EXPECT_THROW(surface::assign_regions(options, s), vesica::Error);
}

}  // namespace
}  // namespace vesica::test
