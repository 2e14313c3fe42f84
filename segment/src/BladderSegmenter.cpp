#include "vesica/segment/BladderSegmenter.h"

#include <sstream>

#include "ImageOps.h"
#include "MrIntensity.h"
#include "UrineRegion.h"
#include "vesica/core/Error.h"
#include "vesica/segment/AutoSeed.h"

namespace vesica::segment {
namespace {

using namespace ops;

// CT border clamps (HU) around the urine level U: never below U - 60 (fat-side partial
// volumes), at least 5 below U. Air beyond the image.
constexpr double kCtFloorGapHu = 60.0, kCtMinGapHu = 5.0, kCtAirHu = -1000.0;

void check_seed_inside(const Float& image, const std::array<double, 3>& seed_mm,
                       const std::string& source) {
  Float::PointType p;
  for (int i = 0; i < 3; ++i) p[i] = seed_mm[i];
  Index k;
  if (image.TransformPhysicalPointToIndex(p, k)) return;
  std::ostringstream m;
  m << "seed (" << p[0] << ", " << p[1] << ", " << p[2] << ") mm lies outside the image";
  fail(source, m.str(), "give --seed in patient millimetres (LPS) inside the volume");
}

// The seed given, or the one automatic seeding finds on `image` with window `a`.
void choose_seed(const Float& image, const AutoSeedParams& a, const SegmentParams& p,
                 const std::string& source, SegmentResult& r) {
  if (p.seed_mm) {
    r.seed_mode = "manual";
    r.seed_mm = *p.seed_mm;
    return;
  }
  const auto found = find_bladder_seed(image, a);
  if (!found)
    fail(source, "automatic seeding found no compact urine-like region in the pelvis",
         "give --seed x,y,z (LPS mm) inside the bladder");
  r.seed_mode = "auto";
  r.seed_mm = found->seed_mm;
  r.diagnostics["auto_seed_candidates"] = found->candidates;
}

Float::PointType point_of(const std::array<double, 3>& mm) {
  Float::PointType p;
  for (int i = 0; i < 3; ++i) p[i] = mm[i];
  return p;
}

void segment_ct(const Float& image, const SegmentParams& p, const std::string& source,
                SegmentResult& r) {
  UrineWindow w;
  w.lower = p.lower_hu;
  w.upper = p.upper_hu;
  w.floor_gap = kCtFloorGapHu;
  w.min_gap = kCtMinGapHu;
  w.outside = kCtAirHu;
  w.units = "HU";
  AutoSeedParams a;
  a.lower = w.lower;
  a.upper = w.upper;
  a.outside = w.outside;
  choose_seed(image, a, p, source, r);
  r.intensity_units = w.units;
  r.window_lower = w.lower;
  r.window_upper = w.upper;
  segment_urine_region(image, point_of(r.seed_mm), w, p, source, r);
}

void segment_mr(const Float& image, const SegmentParams& p, const std::string& source,
                SegmentResult& r) {
  const auto choose = [&](const Float& normalised, double auto_seed_level) {
    AutoSeedParams a;
    a.lower = auto_seed_level;
    a.upper = 1e30;
    a.outside = 0.0;
    choose_seed(normalised, a, p, source, r);
  };
  const MrModel m = model_mr_intensities(image, p, source, choose, r);
  r.intensity_units = m.window.units;
  r.window_lower = m.window.lower;
  r.window_upper = m.window.upper;
  segment_urine_region(*m.normalised, point_of(r.seed_mm), m.window, p, source, r);
}

}  // namespace

SegmentResult segment_bladder(const ScanImage& image, const SegmentParams& p,
                              const std::string& source) {
  if (p.seed_mm) check_seed_inside(image, *p.seed_mm, source);
  SegmentResult r;
  if (p.modality == Modality::CT)
    segment_ct(image, p, source, r);
  else
    segment_mr(image, p, source, r);
  // Label sanity: one component (kept), holes filled (done), and not a speck.
  const double ml = count(*r.label) * voxel_ml(*r.label);
  if (ml < p.min_volume_ml) {
    std::ostringstream m;
    m.precision(4);
    m << "the segmented bladder holds only " << ml << " ml (less than --min-volume-ml "
      << p.min_volume_ml << ")";
    fail(source, m.str(), "check --seed (LPS mm): it may lie outside the bladder");
  }
  return r;
}

}  // namespace vesica::segment
