#pragma once
// A guard in front of GDCM. Debian builds GDCM with assertions, and GDCM trusts a file's
// structure: a meta header cut short or with an unknown value representation aborts the
// process from inside its reader, and an element whose length field lies makes it
// allocate that length (up to 4 GB) before it notices the file is shorter. So before a
// file reaches GDCM its structure is walked here: the file meta group (explicit VR little
// endian, as the standard fixes it), then the whole data set in the transfer syntax the
// meta group names, sequences, items and encapsulated pixel fragments included. Every
// length must fit in what remains of the file or of its enclosing item; nesting depth and
// element count are bounded. This is a structure check, not a parser: values are left
// to GDCM.
#include <filesystem>

namespace vesica::segment {

enum class DicomFileKind {
  Part10,     // preamble, "DICM" and a complete file meta information group
  NotPart10,  // no "DICM" marker: a raw data set or not DICOM at all
};

// Throws vesica::Error(file, "truncated or corrupt DICOM file (...)") for a file that
// carries the DICM marker but whose structure is inconsistent (or that has a DICOM
// extension, .dcm, .dicom or .ima, and is shorter than a header). A deflated or unknown
// transfer syntax is refused: its data set cannot be walked.
DicomFileKind check_dicom_file(const std::filesystem::path& file);

// True for the extensions DICOM exporters give their files.
bool has_dicom_extension(const std::filesystem::path& file);

}  // namespace vesica::segment
