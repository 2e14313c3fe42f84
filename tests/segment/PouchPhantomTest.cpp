// The phantom's neobladder pouch is the surface stage's (the same field from core's
// PouchShape.h, scaled to the same volume), and its volume integral is exact enough to be
// the truth segmentations are judged against.
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/segment/BladderShape.h"
#include "vesica/segment/LabelStatistics.h"
#include "vesica/segment/Phantom.h"
#include "vesica/surface/Shapes.h"
#include "vesica/surface/TriangleSurface.h"

namespace seg = vesica::segment;
namespace surface = vesica::surface;

TEST(ShapeIntegral, EllipsoidVolumeAndCentroidToOnePartInTenThousand) {
  const double a = 50, b = 40, c = 30, z0 = 7;  // semi-axes and centre height, mm
  const auto r = seg::integrate_mirror_symmetric(
      [&](double x, double y, double z) {
        return x * x / (a * a) + y * y / (b * b) + (z - z0) * (z - z0) / (c * c) - 1;
      },
      a + 1, b + 1, z0 - c - 1, z0 + c + 1, 400);
  EXPECT_NEAR(r.volume_mm3, 4.0 / 3.0 * M_PI * a * b * c, 1e-4 * 4.0 / 3.0 * M_PI * a * b * c);
  EXPECT_NEAR(r.centroid_z_mm, z0, 1e-3);
}

TEST(PouchPhantom, IsTheSurfaceStagesPouch) {
  for (const double elongation : {1.0, 2.0}) {
    surface::ShapeSpec spec;
    spec.kind = surface::ShapeKind::Pouch;
    spec.volume_ml = 300;
    spec.elongation = elongation;
    spec.edge_mm = 2.0;
    const surface::TriangleSurface s = surface::make_shape(spec);
    seg::BladderShapeSpec b;
    b.shape = seg::PhantomShape::Pouch;
    b.volume_ml = 300;
    b.elongation = elongation;
    b.center_mm = {0, 0, 0};  // the surface stage builds its pouch about the origin
    const seg::BladderShape pouch(b);
    int off = 0;
    for (Eigen::Index v = 0; v < s.V.rows(); ++v) {
      const std::array<double, 3> p = {s.V(v, 0), s.V(v, 1), s.V(v, 2)};
      // Every vertex of the surface lies within 0.25 mm of the phantom's pouch wall.
      if (!pouch.inside(p, 0.25) || pouch.inside(p, -0.25)) ++off;
    }
    EXPECT_EQ(off, 0) << "elongation " << elongation << ": " << off << " of " << s.V.rows();
    EXPECT_NEAR(s.V.col(2).minCoeff(), pouch.lowest_z_mm(), 0.25);  // the outlet
  }
}

TEST(PouchPhantom, VoxelisedPouchHoldsItsVolume) {
  seg::PhantomSpec spec;
  spec.shape = seg::PhantomShape::Pouch;
  spec.elongation = 1.5;
  spec.bladder_ml = 300;
  spec.spacing_mm = 1.0;
  spec.fov_mm = {200, 160, 180};
  spec.noise_hu = 0;
  const auto truth = seg::phantom_truth(spec);
  EXPECT_DOUBLE_EQ(truth.bladder_volume_ml, 300.0);
  const auto image = seg::make_phantom(spec);
  const auto stats = seg::label_statistics(*seg::phantom_bladder_mask(spec, *image));
  EXPECT_NEAR(stats.volume_ml, 300.0, 1.5);  // voxel-centre count on 1 mm voxels
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(stats.centroid_mm[i], truth.bladder_center_mm[i], 0.2);
  EXPECT_LT(truth.bladder_center_mm[2], -10.0);  // the neck pulls the centroid down
}
