#pragma once
// One entry point for every input the segment stage accepts: a DICOM folder or a
// NIfTI / NRRD / MetaImage volume. Values are returned as float (HU for CT, the stored
// signal for MR). Whatever the format, the geometry must be finite (spacing > 0, finite
// origin, an invertible direction) and every voxel a finite number.
#include <filesystem>
#include <string>

#include "vesica/io/LabelMap.h"
#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct Volume {
  ScanImage::Pointer image;
  std::string series_key;    // DICOM only: series_key() of the series read, never its UID
  std::string modality;      // DICOM only: the header's Modality ("CT", "MR", ...)
  double echo_time_ms = -1;  // DICOM MR only
  std::string format;        // "dicom", "nifti", "nrrd", "metaimage"
};

// `series` picks a series in a DICOM folder by key or UID (ignored for volume files).
Volume read_volume(const std::filesystem::path& input, const std::string& series);

// The label map as io writes it (io::write_label_map: NIfTI, NRRD, MetaImage, or a 3D Slicer
// segmentation with its segment keys for .seg.nrrd); voxels 1 inside, 0 outside.
io::LabelMap to_label_map(const LabelImage& label);

}  // namespace vesica::segment
