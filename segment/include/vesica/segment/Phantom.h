#pragma once
// A synthetic pelvis with a urine-filled bladder of exactly known volume, as a CT (HU) or
// as a T2-weighted MR (scanner units: bright urine, intermediate wall and muscle, fat
// bright or suppressed, a smooth multiplicative bias field, Rician noise). The anatomy is
// analytic (ellipses, ellipsoids and the surface stage's pouch, in patient millimetres,
// LPS), so the bladder volume and centre are exact and independent of the voxel grid; the
// grid may be axial or oblique, have thick slices, and be stored in either slice order.
#include <array>

#include "vesica/segment/DicomSeriesWriter.h"
#include "vesica/segment/ImageTypes.h"
#include "vesica/segment/PhantomSpec.h"

namespace vesica::segment {

struct PhantomTruth {
  double bladder_volume_ml = 0;               // exact (the pouch: integrated, < 1e-4)
  std::array<double, 3> bladder_center_mm{};  // LPS; the urine's centroid
  std::array<double, 3> bladder_semi_axes_mm{};
};

PhantomTruth phantom_truth(const PhantomSpec& spec);

// The phantom image (HU or MR signal) with partial-volume averaging at tissue borders and
// noise. Geometry (origin, spacing, direction) follows spec.
ScanImage::Pointer make_phantom(const PhantomSpec& spec);

// 1 inside the analytic bladder (voxel centre test) on the grid of `like`.
LabelImage::Pointer phantom_bladder_mask(const PhantomSpec& spec, const ScanImage& like);

// The MR bias field at a patient point: 1 + bias_fraction * q, q a smooth low-order
// polynomial of the position that reaches exactly +-1 at corners of the field of view.
double mr_bias_field(const PhantomSpec& spec, const std::array<double, 3>& p_mm);

// What the series' DICOM header says: modality, description, and for MR the acquisition
// (echo and repetition times, field strength, sequence, fat suppression, slice geometry).
DicomSeriesHeader phantom_series_header(const PhantomSpec& spec);

}  // namespace vesica::segment
