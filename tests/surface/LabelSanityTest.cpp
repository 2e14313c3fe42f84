// A label map becomes a bladder surface only when it is one piece of some size, and then
// with that piece's enclosed volume: never rescaled to stray blobs or a hollow shell.
#include "vesica/surface/LabelSanity.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "SurfaceTestSupport.h"
#include "TestData.h"
#include "vesica/core/Error.h"
#include "vesica/io/LabelMap.h"
#include "vesica/surface/TriangleSurface.h"

namespace {

using vesica::surface::LabelVolume;
using Inside = std::function<bool(const Eigen::Vector3d&)>;

constexpr int kGrid = 80;

// A 1 mm grid of kGrid^3 voxels, voxel centres at their index (mm).
LabelVolume grid_label(const Inside& inside) {
  LabelVolume l;
  l.size = {kGrid, kGrid, kGrid};
  l.inside.resize(static_cast<std::size_t>(kGrid) * kGrid * kGrid);
  std::size_t v = 0;
  for (int k = 0; k < kGrid; ++k)
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) l.inside[v++] = inside(Eigen::Vector3d(i, j, k)) ? 1 : 0;
  return l;
}

Inside ball(const Eigen::Vector3d& centre, double radius) {
  return [=](const Eigen::Vector3d& x) { return (x - centre).norm() <= radius; };
}

// Lattice points of a ball counted directly: the voxel count of that piece alone.
std::size_t count(const Inside& inside) {
  std::size_t n = 0;
  for (int k = 0; k < kGrid; ++k)
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i) n += inside(Eigen::Vector3d(i, j, k));
  return n;
}

const Inside kLarge = ball({25, 25, 25}, 20), kSmall = ball({60, 60, 60}, 14);
const Inside kTwoBlobs = [](const Eigen::Vector3d& x) { return kLarge(x) || kSmall(x); };

}  // namespace

TEST(LabelSanity, TwoBlobsAreRefusedUnlessTheLargestIsChosen) {
  LabelVolume label = grid_label(kTwoBlobs);
  try {
    vesica::surface::clean_label({}, "two.nii.gz", label);
    FAIL() << "two blobs accepted";
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find("2 separate pieces"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("--component largest"), std::string::npos) << e.what();
  }
  const auto cleanup = vesica::surface::clean_label({"largest", 1.0}, "two.nii.gz", label);
  EXPECT_EQ(cleanup.components, 2);
  EXPECT_EQ(label.voxel_count(), count(kLarge));
  EXPECT_EQ(cleanup.dropped_voxels, count(kSmall));
}

TEST(LabelSanity, TheSurfaceOfTheKeptBlobHasTheKeptBlobsVolume) {
  const auto dir = vesica::test::scratch_dir("surface-two-blobs");
  const LabelVolume label = grid_label(kTwoBlobs);
  vesica::io::LabelMap map;
  map.size = label.size;
  map.voxels = label.inside;
  vesica::io::write_label_map(map, dir / "two.nii.gz");
  vesica::surface::SurfaceStageOptions options;
  options.input = (dir / "two.nii.gz").string();
  options.output = (dir / "kept.vtp").string();
  options.edge_mm = 2.5;
  options.label_sanity.component = "largest";
  nlohmann::json summary;
  const auto surface = vesica::test::run_stage(options, &summary);
  // Kept: the 20 mm ball's voxels (1 mm^3 each), not both blobs'.
  EXPECT_NEAR(summary["label_volume_ml"].get<double>(), count(kLarge) * 1e-3, 1e-9);
  const double analytic_ml = 4.0 / 3.0 * M_PI * std::pow(20.0, 3) * 1e-3;
  EXPECT_NEAR(vesica::surface::enclosed_volume(surface.V, surface.F) * 1e-3, analytic_ml,
              0.01 * analytic_ml);
}

TEST(LabelSanity, AHollowLabelIsFilledToItsEnclosedVolume) {
  const Inside outer = ball({40, 40, 40}, 25), inner = ball({40, 40, 40}, 15);
  LabelVolume label = grid_label([&](const Eigen::Vector3d& x) { return outer(x) && !inner(x); });
  const auto cleanup = vesica::surface::clean_label({}, "shell.nii.gz", label);
  EXPECT_EQ(label.voxel_count(), count(outer));
  EXPECT_EQ(cleanup.filled_voxels, count(inner));
  ASSERT_FALSE(cleanup.notes.empty());
  EXPECT_NE(cleanup.notes.back().find("filled"), std::string::npos);
}

TEST(LabelSanity, AOneVoxelBladderIsRefused) {
  LabelVolume label =
      grid_label([](const Eigen::Vector3d& x) { return x == Eigen::Vector3d(5, 5, 5); });
  EXPECT_THROW(vesica::surface::clean_label({}, "dot.nii.gz", label), vesica::Error);
}

TEST(LabelSanity, SpecksBesideTheBladderAreDroppedWithANote) {
  const Inside speck = ball({70, 70, 70}, 1);  // 7 voxels, far below 1 % of the ball
  LabelVolume label = grid_label([&](const Eigen::Vector3d& x) { return kLarge(x) || speck(x); });
  const auto cleanup = vesica::surface::clean_label({}, "specks.nii.gz", label);
  EXPECT_EQ(label.voxel_count(), count(kLarge));
  EXPECT_EQ(cleanup.dropped_voxels, count(speck));
  ASSERT_FALSE(cleanup.notes.empty());
  EXPECT_NE(cleanup.notes.front().find("dropped"), std::string::npos);
}
