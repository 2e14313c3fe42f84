#pragma once
// One entry point for every input the segment stage accepts: a DICOM folder or a
// NIfTI / NRRD / MetaImage volume. Values are returned as float (HU for CT).
#include <filesystem>
#include <string>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct Volume {
  CtImage::Pointer image;
  std::string series_uid;  // DICOM only
  std::string modality;    // DICOM only
  std::string format;      // "dicom", "nifti", "nrrd", "metaimage"
};

// `series_uid` picks a series in a DICOM folder (ignored for volume files).
Volume read_volume(const std::filesystem::path& input, const std::string& series_uid);

// Writes a label map (format from the extension); used through write_atomically.
void write_label(const LabelImage& label, const std::filesystem::path& path);

}  // namespace vesica::segment
