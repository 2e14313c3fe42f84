#pragma once
// DICOM folders: find the series in a folder (grouped by SeriesInstanceUID), check that
// a series is a complete, consistent, evenly spaced stack, and read it (HU for CT, the
// stored values for MR) with the geometry taken from ImagePositionPatient /
// ImageOrientationPatient (not from SliceThickness, which scanners fill inconsistently).
// Compressed transfer syntaxes (JPEG, JPEG 2000, RLE) are decoded by GDCM. No patient
// field is ever read out, and a UID never leaves this file except as its series key.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct DicomSlice {
  std::string file;
  std::array<double, 3> position_mm{};  // ImagePositionPatient
  std::array<double, 6> orientation{};  // ImageOrientationPatient (row, column cosines)
  std::array<unsigned, 2> columns_rows{};
  std::array<double, 2> pixel_spacing_mm{};  // along a row, along a column
  std::string pixel_format;                  // samples, bits allocated, representation
  double echo_time_ms = -1;                  // EchoTime; -1 when absent (CT)
};

struct DicomSeries {
  std::string uid;  // may be empty: some exporters blank it. Never written out: see key()
  std::string modality;
  std::string description;
  std::array<double, 6> orientation{};  // of the first slice
  std::array<unsigned, 2> columns_rows{};
  std::array<double, 2> pixel_spacing_mm{};
  double echo_time_ms = -1;
  std::vector<DicomSlice> slices;  // sorted along the slice normal
  // Set when a slice's geometry is unusable (not finite, not orthonormal); reading the
  // series then fails with it, naming problem_file.
  std::string problem, problem_file;

  double slice_spacing_mm() const;  // from positions; 0 for a single slice
  std::string key() const;          // series_key(uid)
};

// The name a series goes by in vesica's outputs and listings: a salted SHA-256 of its
// SeriesInstanceUID (16 hex digits), so that series can be told apart and matched
// without a UID, an identifier under de-identification rules, ever being copied.
std::string series_key(const std::string& uid);

// All series in `folder` (not recursive). Files that are not DICOM are ignored; a file
// that is DICOM (DICM marker or .dcm/.dicom/.ima) but unreadable or cut short is an
// error naming it. Throws vesica::Error when the folder is missing, empty or holds no
// DICOM image.
std::vector<DicomSeries> scan_dicom_folder(const std::filesystem::path& folder);

// The series to read: `wanted` (a series key from --list-series, or the UID itself) when
// given, else the only series. Several series without a choice is an error that lists
// how many (the caller shows --list-series).
const DicomSeries& choose_series(const std::vector<DicomSeries>& all, const std::string& wanted,
                                 const std::filesystem::path& folder);

// Checks geometry (finite, one orientation, equal spacing, no missing or duplicate
// slice), that every slice has the same size, pixel spacing, pixel format and echo time,
// and reads the pixels (rescale slope/intercept applied). Throws vesica::Error naming
// the offending file.
ScanImage::Pointer read_dicom_series(const DicomSeries& series,
                                     const std::filesystem::path& folder);

}  // namespace vesica::segment
