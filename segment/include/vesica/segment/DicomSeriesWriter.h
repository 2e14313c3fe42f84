#pragma once
// Writes a CT volume as a DICOM series (one file per slice) through ITK's GDCMImageIO:
// freshly generated Study/Series/SOP Instance UIDs, the geometry tags of every slice
// (ImagePositionPatient, ImageOrientationPatient, PixelSpacing, SliceThickness) and
// stored values with a rescale intercept. Patient fields carry only a placeholder.
#include <filesystem>
#include <string>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct DicomSeriesInfo {
  std::string study_uid;
  std::string series_uid;
  std::string series_description = "VESICA synthetic pelvic phantom";
  int slice_count = 0;
};

// Writes slices as DIR/slice_0001.dcm ... in storage order (index k of `image`).
DicomSeriesInfo write_dicom_series(const CtImage& image, const std::filesystem::path& dir,
                                   const std::string& series_description);

}  // namespace vesica::segment
