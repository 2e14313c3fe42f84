// T2-weighted MR phantoms, axial and oblique, at 1 mm and at 0.7 x 0.7 x 3.5 mm slices,
// with a +-30 % bias field and Rician noise, segmented with the documented defaults and
// compared with the phantom's exact bladder: Dice >= 0.95 and volume within 3 % (issue 23).
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "SegmentTestHelpers.h"
#include "vesica/segment/BladderSegmenter.h"
#include "vesica/segment/LabelStatistics.h"
#include "vesica/segment/Phantom.h"

namespace seg = vesica::segment;
using vesica::test::read_json;
using vesica::test::read_text;
using vesica::test::run_tool;

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

// The neobladder pouch (the surface stage's shape) as CT and as thick oblique fat-suppressed
// MR: the same acceptance as the bladder.
TEST(NeobladderPouch, SegmentedFromCtAndFromThickObliqueMr) {
  for (const auto modality : {seg::Modality::CT, seg::Modality::MR}) {
    seg::PhantomSpec spec;
    spec.modality = modality;
    spec.shape = seg::PhantomShape::Pouch;
    spec.elongation = 1.5;
    spec.bladder_ml = 350;
    spec.fov_mm = {200, 180, 180};
    spec.spacing_mm = modality == seg::Modality::CT ? 1.5 : 0.7;
    spec.slice_spacing_mm = modality == seg::Modality::CT ? 0.0 : 3.5;
    spec.orientation = modality == seg::Modality::CT ? seg::PhantomOrientation::Axial
                                                     : seg::PhantomOrientation::Oblique;
    spec.mr.fat_suppression = true;
    const auto truth = seg::phantom_truth(spec);
    const auto image = seg::make_phantom(spec);
    seg::SegmentParams params;
    params.modality = modality;
    params.seed_mm = truth.bladder_center_mm;
    const auto label = seg::segment_bladder(*image, params, "pouch").label;
    const double d = seg::dice(*label, *seg::phantom_bladder_mask(spec, *image));
    const double ml = seg::label_statistics(*label).volume_ml;
    const std::string name = seg::modality_name(modality);
    RecordProperty(name + "_dice", std::to_string(d));
    RecordProperty(name + "_volume_ml", std::to_string(ml));
    EXPECT_GE(d, 0.95) << name;
    EXPECT_NEAR(ml, 350.0, 0.03 * 350.0) << name;
  }
}

// Through both executables and a DICOM series, as a user runs it: the modality from the
// header, the seed found automatically, the label on the thick oblique input grid.
TEST(MrThroughTheTools, AutoSeededPouchFromItsDicomSeries) {
  const auto dir = vesica::test::scratch_dir("segment-mr-tools");
  ASSERT_EQ(run_tool("vesica-phantom",
                     "-o " + (dir / "mr").string() +
                         " --modality mr --shape pouch --elongation 1.5 --orientation oblique"
                         " --spacing-mm 0.7 --slice-spacing-mm 3.5 --fov-mm 200,200,160"
                         " --report " +
                         (dir / "phantom.json").string(),
                     dir),
            0)
      << read_text(dir / "stderr.txt");
  ASSERT_EQ(run_tool("vesica-segment",
                     (dir / "mr").string() + " -o " + (dir / "bladder.nii.gz").string() +
                         " --report " + (dir / "segment.json").string(),
                     dir),
            0)
      << read_text(dir / "stderr.txt");
  const auto truth = read_json(dir / "phantom.json");
  const auto summary = read_json(dir / "segment.json");
  EXPECT_EQ(summary["modality"], "MR");
  EXPECT_EQ(summary["seed_mode"], "auto");
  EXPECT_EQ(summary["image_size"], truth["image_size"]);
  const double exact = truth["bladder_volume_ml"];
  EXPECT_NEAR(summary["volume_ml"].get<double>(), exact, 0.03 * exact);
  const auto stats = seg::label_statistics(*vesica::test::read_label(dir / "bladder.nii.gz"));
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(stats.centroid_mm[i], truth["bladder_center_mm"][i].get<double>(), 2.0);
}

// The runner's phantom subcommand passes the MR options through, and the MR demo
// pipeline is a valid pipeline file (make demo runs the CT one; this one is run by hand).
TEST(MrDemo, PhantomSubcommandAndPipelineFile) {
  const auto dir = vesica::test::scratch_dir("segment-mr-demo");
  ASSERT_EQ(run_tool("vesica",
                     "phantom " + (dir / "mr").string() +
                         " --modality mr --spacing-mm 5 --slice-spacing-mm 10 --fov-mm 200,200,150"
                         " --report " +
                         (dir / "phantom.json").string(),
                     dir),
            0)
      << read_text(dir / "stderr.txt");
  const auto report = read_json(dir / "phantom.json");
  EXPECT_EQ(report["modality"], "MR");
  EXPECT_EQ(report["slice_count"], 15);
  const auto file = vesica::test::source_dir() / "pipelines" / "mr-demo.yaml";
  EXPECT_EQ(run_tool("vesica", "validate " + file.string(), dir), 0)
      << read_text(dir / "stdout.txt") << read_text(dir / "stderr.txt");
}
