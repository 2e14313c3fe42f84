#pragma once
// Writes a volume as a DICOM series (one file per slice) through ITK's GDCMImageIO:
// freshly generated Study/Series/SOP Instance UIDs and the geometry tags of every slice
// (ImagePositionPatient, ImageOrientationPatient, PixelSpacing, SliceThickness). CT:
// CT Image Storage, values in HU stored with a rescale intercept, a placeholder patient
// name. MR: MR Image Storage, the values as stored integers, no patient field at all.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "vesica/segment/ImageTypes.h"
#include "vesica/segment/Modality.h"

namespace vesica::segment {

struct DicomSeriesHeader {
  Modality modality = Modality::CT;
  std::string series_description = "VESICA synthetic pelvic phantom";
  // Further attributes, the same on every slice: ("gggg|eeee", value).
  std::vector<std::pair<std::string, std::string>> attributes;
};

struct DicomSeriesInfo {
  std::string study_uid;
  std::string series_uid;
  int slice_count = 0;
};

// Writes slices as DIR/slice_0001.dcm ... in storage order (index k of `image`).
DicomSeriesInfo write_dicom_series(const ScanImage& image, const std::filesystem::path& dir,
                                   const DicomSeriesHeader& header);

// A CT series with the given description.
DicomSeriesInfo write_dicom_series(const ScanImage& image, const std::filesystem::path& dir,
                                   const std::string& series_description);

// "a\b\c" as DICOM decimal strings (DS), never in scientific notation for tiny values.
std::string dicom_decimals(std::initializer_list<double> values);

}  // namespace vesica::segment
