#include "MrIntensity.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include <itkConfidenceConnectedImageFilter.h>
#include <itkImageRegionConstIteratorWithIndex.h>

#include "StepClock.h"
#include "vesica/core/Error.h"
#include "vesica/segment/BiasFieldCorrection.h"

namespace vesica::segment {
namespace {

using namespace ops;

constexpr double kSeedSmoothingMm = 2.0;  // Gaussian sigma before reading the seed region
constexpr unsigned kConfidenceIterations = 4;
// The region steps see MR in percent of the urine level. The unit matters beyond
// readability: the level set weighs its propagation speed, an intensity difference, against
// curvature, and percent gives MR the contrasts CT has in HU (urine to wall ~75, urine to
// fat ~110), so one curvature weight serves both.
constexpr double kUrinePercent = 100.0;
// Where the border may lie (see UrineWindow), in percent of the urine level: never below
// 40 % (darker neighbours' partial volumes), at least 5 % below it.
constexpr double kBorderFloorGap = 60.0, kBorderMinGap = 5.0;
constexpr double kNoUpperBound = 1e30;  // on T2 nothing is brighter than urine to exclude

// The largest value within radius_mm of `seed` (for the message when it is too dark).
double max_within(const Float& image, const Index& seed, double radius_mm) {
  double best = 0;
  const auto box = box_within(image, seed, radius_mm);
  if (!box) return best;
  itk::ImageRegionConstIteratorWithIndex<Float> it(&image, *box);
  for (; !it.IsAtEnd(); ++it) best = std::max(best, static_cast<double>(it.Get()));
  return best;
}

struct UrineStatistics {
  double mean = 0, sigma = 0, volume_ml = 0;
};

// ITK's confidence-connected region grown from the seed: its final mean and spread are
// the urine's, learned where the user (or automatic seeding) pointed.
UrineStatistics learn_urine(const Float& image, const Index& start, const MrParams& p) {
  auto cc = itk::ConfidenceConnectedImageFilter<Float, Mask>::New();
  cc->SetInput(&image);
  cc->SetSeed(start);
  cc->SetMultiplier(p.window_sigmas);
  cc->SetNumberOfIterations(kConfidenceIterations);
  cc->SetInitialNeighborhoodRadius(1);
  cc->SetReplaceValue(1);
  cc->Update();
  UrineStatistics u;
  u.mean = cc->GetMean();
  u.sigma = std::sqrt(std::max(0.0, static_cast<double>(cc->GetVariance())));
  u.volume_ml = count(*cc->GetOutput()) * voxel_ml(image);
  return u;
}

[[noreturn]] void no_bright_region(const std::string& source, double brightest, const MrParams& p) {
  std::ostringstream m;
  m.precision(2);
  m << "no bright (urine) region near the seed: its surroundings reach " << brightest
    << " of the image's bright reference, T2 urine reads at least " << p.min_brightness;
  fail(source, m.str(), "give --seed x,y,z (LPS mm) inside the bladder; is this a T2-weighted MR?");
}

}  // namespace

MrModel model_mr_intensities(const Float& image, const SegmentParams& p, const std::string& source,
                             const SeedChooser& choose_seed, SegmentResult& result) {
  const MrParams& mp = p.mr;
  auto& diag = result.diagnostics["mr"];
  StepClock clock(result.diagnostics["step_seconds"]);
  // 1. Bias field (N4) and the body's bright reference: 1 = urine on T2, for now.
  const BiasField bias = estimate_bias_field(image, mp, source);
  auto corrected = corrected_coarse(bias);
  const double reference = percentile_where(*corrected, *bias.body, mp.reference_percentile);
  if (!(reference > 0)) fail(source, "the MR image holds no tissue signal", "check the input");
  auto normalised = remove_bias(*bias.coarse, *bias.log_bias, 1.0 / reference);
  const float* lb = bias.log_bias->GetBufferPointer();
  const std::size_t nb = bias.log_bias->GetLargestPossibleRegion().GetNumberOfPixels();
  std::vector<float> field;
  const auto* body = bias.body->GetBufferPointer();
  for (std::size_t i = 0; i < nb; ++i)
    if (body[i]) field.push_back(std::exp(lb[i]));
  diag["bias_field_range"] = {*std::min_element(field.begin(), field.end()),
                              *std::max_element(field.begin(), field.end())};
  diag["reference_signal"] = reference;
  clock.lap("mr_bias_field");

  // 2. The seed, given or found on the corrected image.
  choose_seed(*normalised, mp.auto_seed_level);
  clock.lap("mr_seed");
  Float::PointType seed;
  for (int i = 0; i < 3; ++i) seed[i] = result.seed_mm[i];

  // 3. The urine's own level and spread, learned from the seed's neighbourhood.
  auto smoothed = gaussian(*normalised, kSeedSmoothingMm);
  Index seed_index;
  smoothed->TransformPhysicalPointToIndex(seed, seed_index);
  const auto bright = threshold(*smoothed, mp.min_brightness, kNoUpperBound);
  const auto start = nearest_inside(*bright, seed_index, p.seed_search_mm);
  if (!start) no_bright_region(source, max_within(*smoothed, seed_index, p.seed_search_mm), mp);
  const UrineStatistics urine = learn_urine(*smoothed, *start, mp);
  diag["urine_signal"] = urine.mean * reference;
  diag["urine_relative_sigma"] = urine.sigma / urine.mean;
  diag["confidence_region_ml"] = urine.volume_ml;
  clock.lap("mr_learn_window");

  // 4. The full-resolution image with urine at 100, and the window learned around it.
  MrModel m;
  m.normalised = remove_bias(image, *bias.log_bias, kUrinePercent / (reference * urine.mean));
  const double depth =
      std::clamp(mp.window_sigmas * urine.sigma / urine.mean, mp.min_window, mp.max_window);
  m.window.lower = kUrinePercent * (1.0 - depth);
  m.window.upper = kNoUpperBound;
  m.window.floor_gap = kBorderFloorGap;
  m.window.min_gap = kBorderMinGap;
  m.window.surroundings_percentile = mp.surroundings_percentile;
  m.window.outside = 0.0;
  m.window.units = "% of the urine signal";
  clock.lap("mr_normalise");
  return m;
}

}  // namespace vesica::segment
