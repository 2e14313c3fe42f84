// Label maps round-trip through vesica_io and VTK's own NIfTI and NRRD readers see the
// same grid; a Slicer segmentation carries the segment keys Slicer reads, and one saved
// the way Slicer writes it (a hand-written header, two segments) gives its bladder.
#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkNrrdReader.h>
#include <vtkPointData.h>

#include <fstream>
#include <sstream>

#include "TestData.h"
#include "vesica/io/LabelMap.h"
#include "vesica/io/SlicerSegmentation.h"

namespace vesica::test {
namespace {

// An ellipsoid of semi-axes 6, 5, 4 voxels in a 20 x 18 x 16 grid, off-axis direction.
io::LabelMap ellipsoid_map() {
  io::LabelMap m;
  m.size = {20, 18, 16};
  m.spacing_mm = {0.75, 1.25, 2.5};
  m.origin_mm = {-120.5, 33.25, 410.0};
  m.direction = {0, 1, 0, -1, 0, 0, 0, 0, 1};  // a quarter turn about z
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 18; ++j)
      for (int i = 0; i < 20; ++i) {
        const double x = (i - 9.5) / 6, y = (j - 8.5) / 5, z = (k - 7.5) / 4;
        m.voxels.push_back(x * x + y * y + z * z <= 1.0 ? 1 : 0);
      }
  return m;
}

void expect_same(const io::LabelMap& a, const io::LabelMap& b) {
  EXPECT_EQ(a.size, b.size);
  EXPECT_EQ(a.spacing_mm, b.spacing_mm);
  EXPECT_EQ(a.origin_mm, b.origin_mm);
  for (int e = 0; e < 9; ++e) EXPECT_NEAR(a.direction[e], b.direction[e], 1e-12);
  EXPECT_EQ(a.voxels, b.voxels);
}

template <class Reader>
void expect_vtk_sees(const std::filesystem::path& file, const io::LabelMap& m) {
  vtkNew<Reader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  double spacing[3];
  image->GetSpacing(spacing);
  for (int d = 0; d < 3; ++d) {
    EXPECT_EQ(dims[d], m.size[d]);
    EXPECT_DOUBLE_EQ(spacing[d], m.spacing_mm[d]);
  }
  vtkDataArray* values = image->GetPointData()->GetScalars();
  ASSERT_NE(values, nullptr);
  std::size_t inside = 0;
  for (vtkIdType v = 0; v < values->GetNumberOfTuples(); ++v) inside += values->GetTuple1(v) != 0;
  EXPECT_EQ(inside, m.voxel_count());
}

TEST(LabelMaps, NiftiRoundTripIsReadAlikeByVtk) {
  const io::LabelMap m = ellipsoid_map();
  // About the analytic 4/3 pi 6 5 4 = 502.7 voxels (a voxelized ellipsoid).
  ASSERT_NEAR(static_cast<double>(m.voxel_count()), 502.7, 0.05 * 502.7);
  const auto file = scratch_dir("io-label-nifti") / "bladder.nii.gz";
  io::write_label_map(m, file);
  expect_same(io::read_label_map(file), m);
  expect_vtk_sees<vtkNIFTIImageReader>(file, m);
}

TEST(LabelMaps, NrrdRoundTripIsReadAlikeByVtk) {
  const io::LabelMap m = ellipsoid_map();
  const auto dir = scratch_dir("io-label-nrrd");
  io::write_label_map(m, dir / "bladder.nrrd");
  expect_same(io::read_label_map(dir / "bladder.nrrd"), m);
  expect_vtk_sees<vtkNrrdReader>(dir / "bladder.nrrd", m);
}

TEST(LabelMaps, SlicerSegmentationNamesTheBladderWithItsColourAndExtent) {
  const io::LabelMap m = ellipsoid_map();
  const auto file = scratch_dir("io-label-seg") / "bladder.seg.nrrd";
  io::write_label_map(m, file);
  std::ifstream in(file, std::ios::binary);
  std::string header, line;
  while (std::getline(in, line) && !line.empty()) header += line + "\n";
  EXPECT_NE(header.find("Segment0_Name:=bladder\n"), std::string::npos) << header;
  EXPECT_NE(header.find("Segment0_ID:=bladder\n"), std::string::npos) << header;
  EXPECT_NE(header.find("Segment0_LabelValue:=1\n"), std::string::npos) << header;
  EXPECT_NE(header.find("Segment0_Layer:=0\n"), std::string::npos) << header;
  EXPECT_NE(header.find("Segment0_Color:=0.85 0.65 0.2\n"), std::string::npos) << header;
  // Semi-axes 6, 5, 4 voxels about (9.5, 8.5, 7.5): i 4..15, j 4..13, k 4..11.
  EXPECT_NE(header.find("Segment0_Extent:=4 15 4 13 4 11\n"), std::string::npos) << header;
  EXPECT_NE(header.find("Segmentation_MasterRepresentation:=Binary labelmap\n"), std::string::npos)
      << header;
  const auto segments = io::read_segments(file);
  ASSERT_EQ(segments.size(), 1u);
  EXPECT_EQ(segments[0].name, "bladder");
  expect_same(io::read_label_map(file), m);
}

// A 4 x 3 x 2 segmentation as Slicer saves it: raw bytes, segment "Prostate" = 1 and
// "Bladder" = 3 in one layer.
TEST(LabelMaps, SegmentationSavedBySlicerGivesItsBladderSegment) {
  const auto file = scratch_dir("io-label-slicer") / "edited.seg.nrrd";
  const unsigned char voxels[24] = {0, 0, 0, 0, 0, 3, 3, 0, 1, 1, 0, 0,
                                    0, 3, 3, 0, 0, 3, 3, 3, 0, 0, 1, 0};
  std::ofstream out(file, std::ios::binary);
  out << "NRRD0004\n# Complete NRRD file format specification at:\n"
         "# http://teem.sourceforge.net/nrrd/format.html\n"
         "type: unsigned char\ndimension: 3\nspace: left-posterior-superior\n"
         "sizes: 4 3 2\nspace directions: (0.5,0,0) (0,0.5,0) (0,0,2)\n"
         "kinds: domain domain domain\nencoding: raw\nspace origin: (-10,20,30)\n"
         "Segment0_Color:=0.564706 0.933333 0.564706\nSegment0_ColorAutoGenerated:=1\n"
         "Segment0_Extent:=0 1 2 2 0 1\nSegment0_ID:=Segment_1\nSegment0_LabelValue:=1\n"
         "Segment0_Layer:=0\nSegment0_Name:=Prostate\nSegment0_NameAutoGenerated:=0\n"
         "Segment0_Tags:=Segmentation.Status:inprogress|\n"
         "Segment1_Color:=0.847059 0.647059 0.207843\nSegment1_ColorAutoGenerated:=0\n"
         "Segment1_Extent:=0 3 0 2 0 1\nSegment1_ID:=Segment_2\nSegment1_LabelValue:=3\n"
         "Segment1_Layer:=0\nSegment1_Name:=Bladder\nSegment1_NameAutoGenerated:=0\n"
         "Segment1_Tags:=Segmentation.Status:inprogress|\n"
         "Segmentation_ContainedRepresentationNames:=Binary labelmap|Closed surface|\n"
         "Segmentation_MasterRepresentation:=Binary labelmap\n"
         "Segmentation_ReferenceImageExtentOffset:=0 0 0\n\n";
  out.write(reinterpret_cast<const char*>(voxels), sizeof voxels);
  out.close();
  const io::LabelMap m = io::read_label_map(file);
  EXPECT_EQ(m.size, (std::array<int, 3>{4, 3, 2}));
  EXPECT_EQ(m.spacing_mm, (std::array<double, 3>{0.5, 0.5, 2.0}));
  EXPECT_EQ(m.origin_mm, (std::array<double, 3>{-10, 20, 30}));
  EXPECT_EQ(m.voxel_count(), 7u);  // the 3s
  for (int v = 0; v < 24; ++v) EXPECT_EQ(m.voxels[v], voxels[v] == 3 ? 1 : 0) << v;
}

// A tool that writes plain NRRD under a .seg.nrrd name (no segment keys): Slicer reads it
// as one segment per label value, vesica as a plain label map.
TEST(LabelMaps, SegNrrdWithoutSegmentKeysIsAPlainLabelMap) {
  const auto dir = scratch_dir("io-label-plain-seg");
  const io::LabelMap m = ellipsoid_map();
  io::write_label_map(m, dir / "plain.nrrd");
  std::filesystem::rename(dir / "plain.nrrd", dir / "plain.seg.nrrd");
  EXPECT_FALSE(io::lists_segments(dir / "plain.seg.nrrd"));
  expect_same(io::read_label_map(dir / "plain.seg.nrrd"), m);
}

}  // namespace
}  // namespace vesica::test
