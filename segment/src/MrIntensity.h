#pragma once
// The MR intensity model: turns a T2-weighted image (arbitrary scanner units, a bias
// field across the coil's view) into one where urine reads 100 everywhere (percent of the
// urine signal), and learns the
// urine window from the seed's neighbourhood, so that the shared region steps can run on
// it as they run on CT in HU.
#include <functional>

#include "UrineRegion.h"

namespace vesica::segment {

struct MrModel {
  ops::Float::Pointer normalised;  // the input without its bias field, urine = 100
  UrineWindow window;
};

// Seeds are chosen through `choose_seed`, called with the bias-corrected image on the
// N4 grid (normalised to the reference percentile) and automatic-seeding parameters for
// it. Throws vesica::Error(source, ...) when no bright region lies near the seed.
using SeedChooser = std::function<void(const ops::Float& image, double auto_seed_level)>;
MrModel model_mr_intensities(const ops::Float& image, const SegmentParams& p,
                             const std::string& source, const SeedChooser& choose_seed,
                             SegmentResult& result);

}  // namespace vesica::segment
