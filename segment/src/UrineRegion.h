#pragma once
// The region steps CT and MR share once the intensity model has made urine a window of
// the image's values: bounding box, working grid, smoothing, window + opening at the
// seed, leak guard, partial-volume border, level set, and the label on the input grid.
#include <string>

#include "ImageOps.h"
#include "vesica/segment/BladderSegmenter.h"

namespace vesica::segment {

// The intensity model, in the units of the image handed to segment_urine_region.
struct UrineWindow {
  double lower = 0, upper = 0;  // finds the urine
  // The border level lies in [U - floor_gap, min(lower, U - min_gap)], U the urine level.
  double floor_gap = 0, min_gap = 0;
  // The surroundings level S is this percentile of the shell (50: the median).
  double surroundings_percentile = 50.0;
  double outside = 0;  // what lies beyond the image (air)
  std::string units;   // for messages and the summary
};

// Fills result.label (on the grid of `image`) and the levels of result. Throws
// vesica::Error(source, ...) when the window selects nothing near the seed.
void segment_urine_region(const ops::Float& image, const ops::Float::PointType& seed,
                          const UrineWindow& window, const SegmentParams& p,
                          const std::string& source, SegmentResult& result);

}  // namespace vesica::segment
