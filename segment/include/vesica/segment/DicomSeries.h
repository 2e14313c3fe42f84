#pragma once
// DICOM folders: find the series in a folder (grouped by SeriesInstanceUID), check that
// a series is a complete, evenly spaced stack, and read it in Hounsfield units with the
// geometry taken from ImagePositionPatient / ImageOrientationPatient (not from
// SliceThickness, which scanners fill inconsistently). Compressed transfer syntaxes
// (JPEG, JPEG 2000, RLE) are decoded by GDCM. No patient field is ever read out.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct DicomSlice {
  std::string file;
  std::array<double, 3> position_mm{};  // ImagePositionPatient
};

struct DicomSeries {
  std::string uid;  // may be empty: some exporters blank it
  std::string modality;
  std::string description;
  std::array<double, 6> orientation{};  // ImageOrientationPatient (row, column cosines)
  std::array<unsigned, 2> columns_rows{};
  std::array<double, 2> pixel_spacing_mm{};  // along a row, along a column
  std::vector<DicomSlice> slices;            // sorted along the slice normal

  double slice_spacing_mm() const;  // from positions; 0 for a single slice
};

// All series in `folder` (not recursive). Files that are not DICOM images are ignored.
// Throws vesica::Error when the folder is missing, empty or holds no DICOM image.
std::vector<DicomSeries> scan_dicom_folder(const std::filesystem::path& folder);

// The series to read: `uid` when given, else the only series. Several series without a
// choice is an error that lists them (the caller shows --list-series).
const DicomSeries& choose_series(const std::vector<DicomSeries>& all, const std::string& uid,
                                 const std::filesystem::path& folder);

// Checks geometry (one orientation, equal spacing, no missing or duplicate slice) and
// reads the pixels in HU. Throws vesica::Error naming the offending file.
CtImage::Pointer read_dicom_series(const DicomSeries& series, const std::filesystem::path& folder);

}  // namespace vesica::segment
