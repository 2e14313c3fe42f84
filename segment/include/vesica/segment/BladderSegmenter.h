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
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "vesica/segment/ImageTypes.h"
#include "vesica/segment/Modality.h"

namespace vesica::segment {

// MR intensity model. Normalised signal: 1 = the urine level learned at the seed (before
// the seed is known: 1 = the reference percentile of the bias-corrected image).
struct MrParams {
  double bias_spacing_mm = 10.0;       // N4 bias-field correction runs on this grid
  int bias_levels = 3;                 // B-spline fitting levels (control grid doubles each)
  int bias_iterations = 10;            // per level (N4's cost: points x iterations)
  double reference_percentile = 99.5;  // of the corrected body signal: urine on T2
  double min_brightness = 0.4;         // the seed's neighbourhood must reach this x reference
  double auto_seed_level = 0.7;        // automatic seeding: compact regions above this
  double window_sigmas = 2.5;          // confidence-connected multiplier (the learned window)
  double min_window = 0.2;             // window floor at least this far below the urine level
  double max_window = 0.5;             // ... and at most this far
  // The surroundings level is this percentile of the shell: the dark detrusor, not the
  // brighter fat that thick slices smear into the shell (CT: the median).
  double surroundings_percentile = 25.0;
};

struct SegmentParams {
  Modality modality = Modality::CT;
  // CT urine window (HU) that finds the bladder: tight, so that tissue of similar density
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
  double min_volume_ml = 5.0;     // smaller results are refused: not a bladder to simulate
  double seed_search_mm = 10.0;   // how far from the seed to look for urine
  // Surroundings sampled in a shell this far outside the region; empty = the modality's
  // default (CT 3-9 mm: wall and soft tissue; MR 1.5-3 mm: the hypointense detrusor).
  std::optional<double> shell_inner_mm, shell_outer_mm;
  double levelset_curvature = 1.0;
  double levelset_band_mm = 4.0;  // the refinement may move the border this far
  int levelset_iterations = 60;
  MrParams mr;

  double shell_inner() const;  // the effective values
  double shell_outer() const;
};

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
