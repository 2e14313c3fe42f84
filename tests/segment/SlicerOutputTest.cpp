// `vesica-segment -o bladder.seg.nrrd` writes what 3D Slicer opens as a segmentation: the
// NRRD header carries the segment keys Slicer reads ("key:=value" lines), and the extent it
// names is the bounding box of the bladder's voxels as ITK reads them back.
#include <gtest/gtest.h>

#include <array>
#include <map>
#include <sstream>

#include <itkImageRegionConstIteratorWithIndex.h>

#include "SegmentTestHelpers.h"

namespace vesica::test {
namespace {

// The "key:=value" lines of a NRRD header (which ends at the first empty line).
std::map<std::string, std::string> nrrd_key_values(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::map<std::string, std::string> keys;
  std::string line;
  while (std::getline(in, line) && !line.empty()) {
    const auto at = line.find(":=");
    if (at != std::string::npos) keys[line.substr(0, at)] = line.substr(at + 2);
  }
  return keys;
}

std::string voxel_extent(const segment::LabelImage& label) {
  std::array<long, 6> box{1L << 30, -1, 1L << 30, -1, 1L << 30, -1};
  itk::ImageRegionConstIteratorWithIndex<segment::LabelImage> it(&label,
                                                                 label.GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it)
    if (it.Get() != 0)
      for (int d = 0; d < 3; ++d) {
        box[2 * d] = std::min<long>(box[2 * d], it.GetIndex()[d]);
        box[2 * d + 1] = std::max<long>(box[2 * d + 1], it.GetIndex()[d]);
      }
  std::ostringstream s;
  for (int k = 0; k < 6; ++k) s << (k ? " " : "") << box[k];
  return s.str();
}

TEST(SlicerOutput, SegmentWritesASegmentationThatSlicerOpensAsTheBladder) {
  const auto dir = scratch_dir("segment-seg-nrrd");
  const auto series = small_series(dir, "ct");
  const auto out = dir / "bladder.seg.nrrd";
  ASSERT_EQ(run_tool("vesica-segment", series.string() + " --seed auto -o " + out.string(), dir), 0)
      << read_text(dir / "stderr.txt");
  auto keys = nrrd_key_values(out);
  EXPECT_EQ(keys.count("Segment0_ID"), 1u);
  EXPECT_EQ(keys.count("Segment0_Color"), 1u);
  EXPECT_EQ(keys.count("Segment0_Tags"), 1u);
  EXPECT_EQ(keys["Segment0_Name"], "bladder");
  EXPECT_EQ(keys["Segment0_LabelValue"], "1");
  EXPECT_EQ(keys["Segment0_Layer"], "0");
  EXPECT_EQ(keys["Segmentation_MasterRepresentation"], "Binary labelmap");
  EXPECT_EQ(keys["Segmentation_ContainedRepresentationNames"].rfind("Binary labelmap", 0), 0u);
  EXPECT_EQ(keys.count("Segmentation_ReferenceImageExtentOffset"), 1u);
  const auto label = read_label(out);
  EXPECT_EQ(keys["Segment0_Extent"], voxel_extent(*label));
}

}  // namespace
}  // namespace vesica::test
