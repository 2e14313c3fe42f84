#pragma once
// The MR bias field: the receive coil's smooth, multiplicative sensitivity, which makes
// urine read brighter near the coil than far from it. ITK's N4 estimates its logarithm
// as a B-spline on a coarse copy of the image, inside a body mask; the correction then
// divides every voxel of the full-resolution image by the interpolated field.
#include <string>

#include "vesica/segment/BladderSegmenter.h"
#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct BiasField {
  ScanImage::Pointer coarse;    // the image on the N4 grid (bias_spacing_mm)
  ScanImage::Pointer log_bias;  // log of the field, on the same grid
  LabelImage::Pointer body;     // where N4 looked: tissue, not air
};

// Throws vesica::Error(source, ...) when the image holds no tissue signal.
BiasField estimate_bias_field(const ScanImage& image, const MrParams& p, const std::string& source);

// scale * image / exp(log_bias), the field interpolated linearly onto the grid of `image`.
ScanImage::Pointer remove_bias(const ScanImage& image, const ScanImage& log_bias, double scale);

// coarse / exp(log_bias) on the N4 grid itself.
ScanImage::Pointer corrected_coarse(const BiasField& field);

}  // namespace vesica::segment
