#pragma once
// What vesica-segment's method takes (BladderSegmenter.h describes the steps): the
// intensity model of each modality and the shared region steps, with the one documented
// default of each (docs/segment.md). Standard headers only, so that the parameter table
// (SegmentParameters.h), which the runner links, can bind to it without ITK.
#include <array>
#include <optional>

#include "vesica/segment/Modality.h"

namespace vesica::segment {

// Surroundings shells (inner, outer distance outside the region, mm). CT: wall and soft
// tissue 3-9 mm out. MR: the detrusor, dark on T2 and always between urine and whatever
// lies beyond, in the first 1.5-3 mm.
inline constexpr std::array<double, 2> kCtShellMm = {3.0, 9.0};
inline constexpr std::array<double, 2> kMrShellMm = {1.5, 3.0};

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
  // final border is placed by the partial-volume rule instead (BladderSegmenter.h, step 5).
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
  // default (kCtShellMm, kMrShellMm).
  std::optional<double> shell_inner_mm, shell_outer_mm;
  double levelset_curvature = 1.0;
  double levelset_band_mm = 4.0;  // the refinement may move the border this far
  int levelset_iterations = 60;
  MrParams mr;

  // The effective shell.
  double shell_inner() const { return shell_inner_mm.value_or(default_shell_mm()[0]); }
  double shell_outer() const { return shell_outer_mm.value_or(default_shell_mm()[1]); }
  const std::array<double, 2>& default_shell_mm() const {
    return modality == Modality::MR ? kMrShellMm : kCtShellMm;
  }
};

}  // namespace vesica::segment
