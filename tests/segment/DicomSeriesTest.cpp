// DICOM series reading: the real JPEG 2000 series (geometry and HU range stated in the
// data README) and the phantom written then read back (axial and oblique, reversed).
#include <gtest/gtest.h>

#include <cmath>

#include <itkMinimumMaximumImageCalculator.h>
#include <vnl/vnl_cross.h>

#include "TestData.h"
#include "vesica/segment/DicomSeries.h"
#include "vesica/segment/DicomSeriesWriter.h"
#include "vesica/segment/Phantom.h"
#include "vesica/segment/VolumeReader.h"

namespace seg = vesica::segment;

TEST(DicomSeries, RealJpeg2000SeriesGeometryAndHounsfieldRange) {
  VESICA_REQUIRE_SHARED(dir, "data/ct/dicom-jpeg2000-series");
  const auto all = seg::scan_dicom_folder(dir);
  ASSERT_EQ(all.size(), 1u);
  EXPECT_EQ(all[0].uid, "");  // the publisher blanked it
  EXPECT_EQ(all[0].slices.size(), 20u);
  const auto v = seg::read_volume(dir, "");
  const auto size = v.image->GetLargestPossibleRegion().GetSize();
  EXPECT_EQ(size[0], 512u);
  EXPECT_EQ(size[1], 512u);
  EXPECT_EQ(size[2], 20u);
  EXPECT_NEAR(v.image->GetSpacing()[0], 0.977, 1e-3);
  EXPECT_NEAR(v.image->GetSpacing()[1], 0.977, 1e-3);
  EXPECT_NEAR(v.image->GetSpacing()[2], 2.0, 1e-3);  // not SliceThickness (3 mm)
  auto mm = itk::MinimumMaximumImageCalculator<seg::ScanImage>::New();
  mm->SetImage(v.image);
  mm->Compute();
  EXPECT_NEAR(mm->GetMinimum(), -1024.0, 0.5);
  EXPECT_NEAR(mm->GetMaximum(), 1839.0, 0.5);
}

namespace {

void expect_round_trip(seg::PhantomOrientation orientation, bool reverse) {
  seg::PhantomSpec spec;
  spec.spacing_mm = 4.0;
  spec.fov_mm = {160, 140, 120};
  spec.orientation = orientation;
  spec.reverse_slices = reverse;
  const auto image = seg::make_phantom(spec);
  // A folder per case: ctest runs the cases side by side, and scratch_dir empties it.
  const auto dir = vesica::test::scratch_dir(
      std::string("dicom-round-trip-") +
      (orientation == seg::PhantomOrientation::Axial ? "axial" : "oblique") +
      (reverse ? "-reversed" : ""));
  const auto info = seg::write_dicom_series(*image, dir / "series", "test");
  const auto v = seg::read_volume(dir / "series", "");
  EXPECT_EQ(v.series_key, seg::series_key(info.series_uid));
  EXPECT_EQ(v.modality, "CT");
  // Same voxels in space: every voxel of the read image maps onto a written voxel with
  // the same HU (rounded to integers when stored).
  const auto size = v.image->GetLargestPossibleRegion().GetSize();
  ASSERT_EQ(size, image->GetLargestPossibleRegion().GetSize());
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(v.image->GetSpacing()[i], 4.0, 1e-6);
  for (itk::IndexValueType k : {0L, 7L, static_cast<itk::IndexValueType>(size[2]) - 1})
    for (itk::IndexValueType j : {3L, 20L})
      for (itk::IndexValueType i : {5L, 17L}) {
        seg::ScanImage::PointType p;
        v.image->TransformIndexToPhysicalPoint({{i, j, k}}, p);
        seg::ScanImage::IndexType w;
        ASSERT_TRUE(image->TransformPhysicalPointToIndex(p, w));
        EXPECT_NEAR(v.image->GetPixel({{i, j, k}}), std::round(image->GetPixel(w)), 0.5);
      }
  // Slices are sorted along the normal, so the read slice axis is never reversed.
  const auto n = v.image->GetDirection().GetVnlMatrix().get_column(2);
  const auto row = v.image->GetDirection().GetVnlMatrix().get_column(0);
  const auto col = v.image->GetDirection().GetVnlMatrix().get_column(1);
  EXPECT_GT(dot_product(n, vnl_cross_3d(row, col)), 0.99);
}

}  // namespace

TEST(DicomSeries, AxialPhantomRoundTrip) {
  expect_round_trip(seg::PhantomOrientation::Axial, false);
}

TEST(DicomSeries, ObliqueReversedPhantomRoundTrip) {
  expect_round_trip(seg::PhantomOrientation::Oblique, true);
}
