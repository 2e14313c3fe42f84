#pragma once
// A guard in front of GDCM. Debian builds GDCM with assertions, and a file cut short
// inside its file meta information (the first few hundred bytes) aborts the whole
// process from inside GDCM's reader. So before a file reaches GDCM its meta header is
// walked here (explicit VR little endian, group 0002 only, as the standard fixes it) and
// every element checked to fit inside the file.
#include <filesystem>

namespace vesica::segment {

enum class DicomFileKind {
  Part10,     // preamble, "DICM" and a complete file meta information group
  NotPart10,  // no "DICM" marker: a raw data set or not DICOM at all
};

// Throws vesica::Error(file, ...) for a file that carries the DICM marker (or a DICOM
// extension: .dcm, .dicom, .ima) but whose header is cut short or malformed.
DicomFileKind check_dicom_file(const std::filesystem::path& file);

// True for the extensions DICOM exporters give their files.
bool has_dicom_extension(const std::filesystem::path& file);

}  // namespace vesica::segment
