// Bad input: each a one-line error naming the problem, exit code != 0, nothing written.
#include <gtest/gtest.h>

#include <fstream>

#include "SegmentTestHelpers.h"

namespace fs = std::filesystem;
namespace seg = vesica::segment;
using vesica::test::read_text;
using vesica::test::run_tool;

using vesica::test::expect_rejected;
using vesica::test::small_series;

TEST(BadInput, EmptyFolder) {
  const auto dir = vesica::test::scratch_dir("segment-bad-empty");
  fs::create_directories(dir / "empty");
  expect_rejected(dir, (dir / "empty").string(), "empty");
}

TEST(BadInput, FolderWithoutDicom) {
  const auto dir = vesica::test::scratch_dir("segment-bad-nodicom");
  fs::create_directories(dir / "notes");
  std::ofstream(dir / "notes" / "readme.txt") << "not an image\n";
  expect_rejected(dir, (dir / "notes").string(), "no DICOM image");
}

TEST(BadInput, TruncatedFile) {
  const auto dir = vesica::test::scratch_dir("segment-bad-truncated");
  const auto series = small_series(dir, "ct");
  const auto victim = series / "slice_0010.dcm";
  fs::resize_file(victim, fs::file_size(victim) / 2);
  expect_rejected(dir, series.string() + " --seed 0,-15,-10", "slice_0010.dcm");
}

TEST(BadInput, SeveralSeriesWithoutChoice) {
  const auto dir = vesica::test::scratch_dir("segment-bad-two-series");
  small_series(dir, "a");
  small_series(dir, "b", 2);
  fs::create_directories(dir / "both");
  for (const char* s : {"a", "b"})
    for (const auto& e : fs::directory_iterator(dir / s))
      fs::copy_file(e.path(), dir / "both" / (std::string(s) + e.path().filename().string()));
  expect_rejected(dir, (dir / "both").string(), "2 series");
  // --list-series names both, without any patient field.
  ASSERT_EQ(run_tool("vesica-segment", (dir / "both").string() + " --list-series", dir), 0);
  const std::string listing = read_text(dir / "stdout.txt");
  EXPECT_EQ(std::count(listing.begin(), listing.end(), '\n'), 2) << listing;
  EXPECT_EQ(listing.find("PHANTOM^"), std::string::npos);
  EXPECT_EQ(listing.find("VESICA^PHANTOM"), std::string::npos);
}

TEST(BadInput, MissingSlice) {
  const auto dir = vesica::test::scratch_dir("segment-bad-gap");
  const auto series = small_series(dir, "ct");
  fs::remove(series / "slice_0015.dcm");
  expect_rejected(dir, series.string() + " --seed 0,-15,-10", "missing slice");
}

TEST(BadInput, SeedOutsideImage) {
  const auto dir = vesica::test::scratch_dir("segment-bad-seed");
  const auto series = small_series(dir, "ct");
  expect_rejected(dir, series.string() + " --seed 0,-15,900", "outside the image");
}

TEST(BadInput, WindowSelectsNothingNearSeed) {
  const auto dir = vesica::test::scratch_dir("segment-bad-window");
  const auto series = small_series(dir, "ct");
  // A seed in the air of the rectum, far from any urine.
  expect_rejected(dir, series.string() + " --seed 0,59.5,-10", "selects nothing near the seed");
}
