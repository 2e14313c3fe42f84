// vesica-segment's and vesica-phantom's parameter tables as users meet them: the tools'
// defaults are the library's (docs/segment.md), a seed is a point or auto, the surroundings
// shell follows the modality unless given, and bad values, inconsistent pairs and a phantom
// grid too large to make are refused in one line naming the options, before any work.
#include <gtest/gtest.h>

#include "SegmentTestHelpers.h"
#include "vesica/phantom/PhantomParameters.h"
#include "vesica/segment/SegmentParameters.h"

namespace fs = std::filesystem;
namespace seg = vesica::segment;
using vesica::ParameterValueError;
using vesica::test::expect_rejected;
using vesica::test::read_text;
using vesica::test::run_tool;
using vesica::test::small_series;

namespace {

// What assigning `text` to the entry `name` says: "" when it is accepted.
std::string refusal(const vesica::ParameterTable& t, const std::string& name,
                    const std::string& text) {
  try {
    t.find(name)->assign(text);
  } catch (const ParameterValueError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(PhantomParameters, TheToolsDefaultsAreTheDocumentedPhantom) {
  const seg::PhantomSpec tool = vesica::phantom::phantom_spec(vesica::phantom::PhantomSettings{});
  // docs/segment.md: a 300 ml sphere, 2 mm voxels over 400 x 400 x 240 mm, CT noise 15 HU;
  // MR bias field 1 +- 0.3 and Rician sigma 2.5 % of urine.
  EXPECT_EQ(tool.bladder_ml, 300.0);
  EXPECT_EQ(tool.spacing_mm, 2.0);
  EXPECT_EQ(tool.fov_mm, (std::array<double, 3>{400, 400, 240}));
  EXPECT_EQ(tool.noise_hu, 15.0);
  EXPECT_EQ(tool.mr.bias_fraction, 0.3);
  EXPECT_EQ(tool.mr.noise_fraction, 0.025);
  const seg::PhantomSpec library;  // what the tests and a library caller start from
  EXPECT_EQ(tool.mr.bias_fraction, library.mr.bias_fraction);
  EXPECT_EQ(tool.mr.noise_fraction, library.mr.noise_fraction);
  const nlohmann::json defaults = vesica::phantom::parameter_table().values();
  EXPECT_EQ(defaults["bias_percent"], 30.0);
  EXPECT_EQ(defaults["noise_percent"], 2.5);
  EXPECT_EQ(defaults["fov_mm"], nlohmann::json({400.0, 400.0, 240.0}));
}

TEST(PhantomParameters, PercentagesBecomeTheSpecsFractions) {
  vesica::phantom::PhantomSettings s;
  const vesica::ParameterTable t = vesica::phantom::parameter_table(s);
  EXPECT_EQ(refusal(t, "bias_percent", "10"), "");
  EXPECT_EQ(refusal(t, "noise_percent", "5"), "");
  EXPECT_DOUBLE_EQ(vesica::phantom::phantom_spec(s).mr.bias_fraction, 0.1);
  EXPECT_DOUBLE_EQ(vesica::phantom::phantom_spec(s).mr.noise_fraction, 0.05);
  EXPECT_EQ(refusal(t, "bias_percent", "95"), "95 is outside [0, 90] %");
  EXPECT_EQ(refusal(t, "fov_mm", "200,0,150"), "'200,0,150': 0 is outside (0, 1000] mm");
  EXPECT_EQ(refusal(t, "fov_mm", "200,150"), "'200,150' is not x,y,z");
}

TEST(PhantomParameters, TheGridIsTheFieldOfViewOverTheSpacing) {
  seg::PhantomSpec spec;
  spec.spacing_mm = 4.0;
  spec.slice_spacing_mm = 5.0;
  spec.fov_mm = {100, 82, 60};
  // By hand: 100 / 4 = 25, 82 / 4 = 20.5 -> 21 (halves round up), 60 / 5 = 12 slices.
  EXPECT_EQ(seg::phantom_grid_size(spec), (std::array<double, 3>{25, 21, 12}));
  EXPECT_EQ(seg::phantom_voxel_count(spec), 25.0 * 21.0 * 12.0);
  const auto size = seg::make_phantom(spec)->GetLargestPossibleRegion().GetSize();
  EXPECT_EQ(size[0], 25u);
  EXPECT_EQ(size[1], 21u);
  EXPECT_EQ(size[2], 12u);
}

TEST(PhantomParameters, AGridTooLargeIsRefusedBeforeAnyWork) {
  const fs::path dir = vesica::test::scratch_dir("phantom-parameters-grid");
  // 400 x 400 x 240 mm at 0.2 mm: 2000 x 2000 x 1200 = 4.8e9 voxels (19 GB as floats).
  EXPECT_EQ(run_tool("vesica-phantom", "-o " + (dir / "big").string() + " --spacing-mm 0.2", dir),
            2);
  const std::string err = read_text(dir / "stderr.txt");
  EXPECT_NE(err.find("--fov-mm 400,400,240 at --spacing-mm 0.2 (slices 0.2 mm apart) is "
                     "2000x2000x1200 = 4.8e+09 voxels, more than 2e+08"),
            std::string::npos)
      << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(fs::exists(dir / "big"));
  // Out of its range: refused at the option, naming it.
  EXPECT_EQ(run_tool("vesica-phantom", "-o " + (dir / "big").string() + " --spacing-mm 0.1", dir),
            2);
  EXPECT_NE(read_text(dir / "stderr.txt").find("--spacing-mm 0.1 is outside [0.2, 10] mm"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "big"));
}

TEST(SegmentParameters, ASeedIsAPointInMillimetresOrAuto) {
  seg::SegmentSettings s;
  const vesica::ParameterTable t = seg::parameter_table(s);
  EXPECT_EQ(t.values()["seed"], "auto");
  EXPECT_EQ(refusal(t, "seed", "12.5,-15,-10"), "");
  ASSERT_TRUE(s.params.seed_mm);
  EXPECT_EQ(*s.params.seed_mm, (std::array<double, 3>{12.5, -15, -10}));
  EXPECT_EQ(t.values()["seed"], nlohmann::json({12.5, -15.0, -10.0}));
  EXPECT_EQ(refusal(t, "seed", "auto"), "");
  EXPECT_FALSE(s.params.seed_mm);
  EXPECT_EQ(refusal(t, "seed", "autoo"),
            "'autoo' is not x,y,z (LPS mm) or auto (did you mean 'auto'?)");
  EXPECT_EQ(refusal(t, "seed", "1,2"), "'1,2' is not x,y,z (LPS mm) or auto");
  EXPECT_EQ(refusal(t, "seed", "1,2,nan"), "'1,2,nan' is not x,y,z (LPS mm) or auto");
}

TEST(SegmentParameters, TheShellIsTheModalitysUnlessGiven) {
  seg::SegmentSettings s;
  const vesica::ParameterTable t = seg::parameter_table(s);
  seg::SegmentParams& p = s.params;
  // docs/segment.md step 6: CT 3-9 mm (wall and soft tissue), MR 1.5-3 mm (the detrusor).
  EXPECT_EQ(p.shell_inner(), 3.0);
  EXPECT_EQ(p.shell_outer(), 9.0);
  p.modality = seg::Modality::MR;
  EXPECT_EQ(p.shell_inner(), 1.5);
  EXPECT_EQ(p.shell_outer(), 3.0);
  EXPECT_EQ(refusal(t, "shell_outer_mm", "12"), "");
  EXPECT_EQ(p.shell_outer(), 12.0);
  EXPECT_EQ(p.shell_inner(), 1.5);
  EXPECT_EQ(t.values()["shell_outer_mm"], 12.0);
  EXPECT_EQ(refusal(t, "shell_outer_mm", "auto"), "");
  EXPECT_EQ(p.shell_outer(), 3.0);
  EXPECT_EQ(t.values()["shell_outer_mm"], "auto");
  EXPECT_EQ(refusal(t, "shell_outer_mm", "0"),
            "0 is outside auto (the modality's: CT 9, MR 3) or (0, 100] mm");
  EXPECT_EQ(t.find("shell_inner_mm")->kind, vesica::Parameter::Kind::Number);
  EXPECT_EQ(t.find("shell_inner_mm")->default_text(), "auto");
}

TEST(SegmentParameters, BadValuesAndInconsistentPairsAreRefusedNamingTheOptions) {
  const fs::path dir = vesica::test::scratch_dir("segment-parameters-refused");
  const std::string ct = small_series(dir, "ct").string();
  expect_rejected(dir, ct + " --roi-radius-mm 5", "--roi-radius-mm 5 is outside [10, 300] mm");
  expect_rejected(dir, ct + " --upper-hu 4000",
                  "--upper-hu 4000 is outside [-1024, 3071] HU: the values a CT stores");
  expect_rejected(dir, ct + " --lower-hu 40 --upper-hu 30", "--lower-hu must be below --upper-hu");
  expect_rejected(dir, ct + " --opening-mm 20 --max-opening-mm 10",
                  "--opening-mm must not exceed --max-opening-mm");
  expect_rejected(dir, ct + " --min-window 0.6 --max-window 0.5",
                  "--min-window must not exceed --max-window");
  // The shell's defaults are the modality's: 10 mm lies beyond CT's outer 9 mm, 4 mm beyond
  // MR's outer 3 mm (and within CT's).
  expect_rejected(dir, ct + " --shell-inner-mm 10",
                  "--shell-inner-mm (10 mm) must be below --shell-outer-mm (9 mm) for CT");
  expect_rejected(dir, ct + " --modality mr --shell-inner-mm 4",
                  "--shell-inner-mm (4 mm) must be below --shell-outer-mm (3 mm) for MR");
}
