#pragma once
// Automatic seeding: the largest compact urine-like blob in the lower part of the scan.
// On a coarse, smoothed copy of the image (CT in HU, or MR normalised) the urine window is
// eroded so that only compact cores survive (bowel loops and vessels are thin), and each
// core is scored by its volume; cores touching the scan border, too small, or in the
// upper part of the body (gallbladder, kidneys, heart) are not candidates.
#include <array>
#include <optional>

#include <nlohmann/json.hpp>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct AutoSeedParams {
  double lower = -20.0, upper = 35.0;  // the urine window, in the image's units
  double outside = -1000.0;            // what lies beyond the image (air)
  double coarse_spacing_mm = 4.0;
  double smoothing_mm = 3.0;     // Gaussian sigma before thresholding
  double core_erosion_mm = 8.0;  // what survives is at least ~16 mm thick
  double min_core_ml = 5.0;
  double max_height_fraction = 0.6;  // centroid in the lower 60 % of the scan (I-S)
};

struct AutoSeed {
  std::array<double, 3> seed_mm{};  // LPS, the deepest point of the chosen core
  double core_ml = 0;
  nlohmann::json candidates;  // every scored core, for the report
};

std::optional<AutoSeed> find_bladder_seed(const ScanImage& image, const AutoSeedParams& p);

}  // namespace vesica::segment
