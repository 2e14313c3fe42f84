// The phantom itself against its analytic description: the voxelised bladder holds the
// analytic volume, and tissues read their nominal HU.
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/segment/LabelStatistics.h"
#include "vesica/segment/Phantom.h"

namespace seg = vesica::segment;

TEST(Phantom, VoxelisedBladderMatchesAnalyticVolumeAndCentre) {
  seg::PhantomSpec spec;
  spec.spacing_mm = 2.0;
  spec.fov_mm = {200, 200, 160};
  spec.noise_hu = 0;
  const auto truth = seg::phantom_truth(spec);
  EXPECT_DOUBLE_EQ(truth.bladder_volume_ml, 300.0);
  // 4/3 pi r^3 = 300 ml -> r = 41.528 mm (hand computed).
  EXPECT_NEAR(truth.bladder_semi_axes_mm[0], 41.528, 1e-3);
  const auto image = seg::make_phantom(spec);
  const auto mask = seg::phantom_bladder_mask(spec, *image);
  const auto stats = seg::label_statistics(*mask);
  EXPECT_NEAR(stats.volume_ml, 300.0, 3.0);  // voxel-centre count, 1 %
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(stats.centroid_mm[i], truth.bladder_center_mm[i], 0.5);
  // Urine at the centre, air outside the body in the corner.
  seg::ScanImage::PointType c;
  for (int i = 0; i < 3; ++i) c[i] = truth.bladder_center_mm[i];
  seg::ScanImage::IndexType k;
  ASSERT_TRUE(image->TransformPhysicalPointToIndex(c, k));
  EXPECT_NEAR(image->GetPixel(k), 10.0, 1e-3);
  EXPECT_NEAR(image->GetPixel({{0, 0, 0}}), -1000.0, 1e-3);
}

TEST(Phantom, EllipsoidKeepsTheRequestedVolume) {
  seg::PhantomSpec spec;
  spec.shape = seg::PhantomShape::Ellipsoid;
  spec.bladder_ml = 450;
  const auto t = seg::phantom_truth(spec);
  const double v = 4.0 / 3.0 * M_PI * t.bladder_semi_axes_mm[0] * t.bladder_semi_axes_mm[1] *
                   t.bladder_semi_axes_mm[2] / 1000.0;
  EXPECT_NEAR(v, 450.0, 1e-9);
  EXPECT_GT(t.bladder_semi_axes_mm[0], t.bladder_semi_axes_mm[2]);
}

TEST(Phantom, PartialVolumeAndNoiseHaveTheRequestedSize) {
  seg::PhantomSpec spec;
  spec.spacing_mm = 3.0;
  spec.fov_mm = {150, 150, 150};
  spec.noise_hu = 15;
  const auto noisy = seg::make_phantom(spec);
  spec.noise_hu = 0;
  const auto clean = seg::make_phantom(spec);
  const std::size_t n = noisy->GetLargestPossibleRegion().GetNumberOfPixels();
  double sum2 = 0;
  std::size_t mixed = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = noisy->GetBufferPointer()[i] - clean->GetBufferPointer()[i];
    sum2 += d * d;
    const float v = clean->GetBufferPointer()[i];
    // Values strictly between fat and urine exist only through partial volume.
    if (v > -99.5f && v < 9.5f) ++mixed;
  }
  EXPECT_NEAR(std::sqrt(sum2 / n), 15.0, 0.2);
  EXPECT_GT(mixed, 500u);
}
