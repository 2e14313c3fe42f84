#pragma once
// Urinary bladder segmentation of a CT volume (HU). The thesis thresholded grey values;
// on real data a bare threshold leaks into neighbouring soft tissue of similar density,
// so the method here is:
//   1. crop a region of interest around the seed;
//   2. edge-preserving smoothing (curvature anisotropic diffusion);
//   3. threshold window for urine, morphological opening (cuts thin bridges into bowel,
//      rectum, vessels), connected component at the seed;
//   4. leak guard: while the component is implausibly large, open harder;
//   5. border placement: the urine level U (median inside) and the level S of the
//      surroundings (median of a shell outside) give the partial-volume border at
//      (U + S) / 2; a threshold-segmentation level set started from the eroded region
//      moves the border there, constrained to a narrow band; holes filled; largest
//      component kept.
// Every parameter has one documented default used for every case (docs/segment.md).
#include <array>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct SegmentParams {
  // Urine window (HU) that finds the bladder: tight, so that tissue of similar density
  // does not connect. Urine reads ~0-20 HU, soft tissue ~40-60 HU, fat ~-100 HU. The
  // final border is placed by the partial-volume rule instead (see above).
  double lower_hu = -20.0;
  double upper_hu = 35.0;
  std::optional<std::array<double, 3>> seed_mm;  // LPS; empty = automatic seeding
  double roi_radius_mm = 100.0;                  // half edge of the cube around the seed
  double work_spacing_mm = 1.5;                  // finer inputs are processed on this grid first
  int diffusion_iterations = 5;
  double diffusion_conductance = 1.0;
  double opening_mm = 6.0;        // radius; cuts bridges thinner than ~2x this
  double max_opening_mm = 15.0;   // leak guard stops opening harder here
  double max_volume_ml = 1500.0;  // larger regions are leaks (the bladder holds <~1 l)
  double seed_search_mm = 10.0;   // how far from the seed to look for urine
  double shell_inner_mm = 3.0;    // surroundings sampled this far outside ...
  double shell_outer_mm = 9.0;    // ... up to this far
  double levelset_curvature = 1.0;
  double levelset_band_mm = 4.0;  // the refinement may move the border this far
  int levelset_iterations = 60;
};

struct SegmentResult {
  LabelImage::Pointer label;                                // on the input grid, 1 = bladder
  std::array<double, 3> seed_mm{};                          // the seed used (given or found)
  std::string seed_mode;                                    // "manual" or "auto"
  double urine_hu = 0, surroundings_hu = 0, border_hu = 0;  // partial-volume rule
  nlohmann::json diagnostics;  // per-step volumes, leak-guard decisions
};

// Throws vesica::Error(source, ...) when the seed lies outside the image or the window
// selects nothing near it.
SegmentResult segment_bladder(const CtImage& ct, const SegmentParams& params,
                              const std::string& source);

}  // namespace vesica::segment
