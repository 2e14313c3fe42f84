#pragma once
// Urinary bladder segmentation of a CT (HU) or a T2-weighted MR volume. The thesis
// thresholded grey values; on real data a bare threshold leaks into neighbouring tissue of
// similar intensity, so the method here is:
//   0. an intensity model: on CT a fixed urine window in HU; on MR the bias field is
//      removed (N4), intensities are normalised, and the urine window is learned from the
//      seed's neighbourhood (confidence-connected statistics);
//   1. crop a region of interest around the seed;
//   2. edge-preserving smoothing (curvature anisotropic diffusion) on an isotropic working
//      grid (thick MR slices are resampled for this; the label returns to the input grid);
//   3. threshold window for urine, morphological opening (cuts thin bridges into bowel,
//      rectum, vessels), connected component at the seed;
//   4. leak guard: while the component is implausibly large, open harder;
//   5. border placement: the urine level U (median inside) and the level S of the
//      surroundings (median of a shell outside) give the partial-volume border at
//      (U + S) / 2; a threshold-segmentation level set started from the eroded region
//      moves the border there, constrained to a narrow band; holes filled; largest
//      component kept.
// Steps 1-5 are one code path for both modalities. Every parameter has one documented
// default used for every case (docs/segment.md).
#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include "vesica/segment/ImageTypes.h"
#include "vesica/segment/SegmentParams.h"

namespace vesica::segment {

struct SegmentResult {
  LabelImage::Pointer label;                  // on the input grid, 1 = bladder
  std::array<double, 3> seed_mm{};            // the seed used (given or found)
  std::string seed_mode;                      // "manual" or "auto"
  std::string intensity_units;                // "HU" or "normalised" (MR, 1 = urine)
  double window_lower = 0, window_upper = 0;  // in intensity_units
  double urine_level = 0, surroundings_level = 0, border_level = 0;  // partial-volume rule
  nlohmann::json diagnostics;  // per-step volumes, leak-guard decisions, MR model
};

// Throws vesica::Error(source, ...) when the seed lies outside the image, nothing
// urine-like lies near it, or the result is smaller than min_volume_ml.
SegmentResult segment_bladder(const ScanImage& image, const SegmentParams& params,
                              const std::string& source);

}  // namespace vesica::segment
