// T2-weighted MR phantoms, axial and oblique, at 1 mm and at 0.7 x 0.7 x 3.5 mm slices,
// with a +-30 % bias field and Rician noise, segmented with the documented defaults and
// compared with the phantom's exact bladder: Dice >= 0.95 and volume within 3 % (issue 23).
#include <gtest/gtest.h>

#include <string>

#include "vesica/segment/BladderSegmenter.h"
#include "vesica/segment/LabelStatistics.h"
#include "vesica/segment/Phantom.h"

namespace seg = vesica::segment;

namespace {

struct MrCase {
  const char* name;
  seg::PhantomOrientation orientation;
  double spacing_mm, slice_spacing_mm;
  seg::PhantomShape shape;
  bool fat_suppression;
};

class MrPhantomSegmentation : public ::testing::TestWithParam<MrCase> {};

}  // namespace

TEST_P(MrPhantomSegmentation, DiceAndVolumeAgainstTheExactBladder) {
  const MrCase& c = GetParam();
  seg::PhantomSpec spec;
  spec.modality = seg::Modality::MR;
  spec.shape = c.shape;
  spec.spacing_mm = c.spacing_mm;
  spec.slice_spacing_mm = c.slice_spacing_mm;
  spec.fov_mm = {180, 180, 140};
  spec.orientation = c.orientation;
  spec.mr.fat_suppression = c.fat_suppression;
  ASSERT_DOUBLE_EQ(spec.mr.bias_fraction, 0.3);     // the defaults are the acceptance's
  ASSERT_DOUBLE_EQ(spec.mr.noise_fraction, 0.025);  // bias field and noise
  const auto truth = seg::phantom_truth(spec);
  const auto image = seg::make_phantom(spec);
  seg::SegmentParams params;  // documented defaults
  params.modality = seg::Modality::MR;
  params.seed_mm = truth.bladder_center_mm;
  const auto result = seg::segment_bladder(*image, params, c.name);
  const auto exact = seg::phantom_bladder_mask(spec, *image);
  const double d = seg::dice(*result.label, *exact);
  const double ml = seg::label_statistics(*result.label).volume_ml;
  RecordProperty("dice", std::to_string(d));
  RecordProperty("volume_ml", std::to_string(ml));
  std::printf("%s: dice %.4f volume %.2f ml (exact %.2f, %+.2f %%) border %.3f S %.3f\n", c.name, d,
              ml, truth.bladder_volume_ml,
              100 * (ml - truth.bladder_volume_ml) / truth.bladder_volume_ml, result.border_level,
              result.surroundings_level);
  EXPECT_GE(d, 0.95);
  EXPECT_NEAR(ml, truth.bladder_volume_ml, 0.03 * truth.bladder_volume_ml);
}

INSTANTIATE_TEST_SUITE_P(Acceptance, MrPhantomSegmentation,
                         ::testing::Values(MrCase{"axial_1mm", seg::PhantomOrientation::Axial, 1.0,
                                                  0.0, seg::PhantomShape::Ellipsoid, false},
                                           MrCase{"oblique_1mm", seg::PhantomOrientation::Oblique,
                                                  1.0, 0.0, seg::PhantomShape::Ellipsoid, true},
                                           MrCase{"axial_thick", seg::PhantomOrientation::Axial,
                                                  0.7, 3.5, seg::PhantomShape::Ellipsoid, true},
                                           MrCase{"oblique_thick", seg::PhantomOrientation::Oblique,
                                                  0.7, 3.5, seg::PhantomShape::Ellipsoid, false}),
                         [](const auto& info) { return std::string(info.param.name); });
