#include "vesica/segment/AutoSeed.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <itkConnectedComponentImageFilter.h>
#include <itkImageRegionConstIteratorWithIndex.h>

#include "ImageOps.h"

namespace vesica::segment {
namespace {

using namespace ops;

struct Core {
  std::size_t voxels = 0;
  std::array<double, 3> sum{};
  bool touches_border = false;
  double best_depth = 0;  // most negative signed distance (deepest point)
  Index deepest{};
};

// Height of a point along the patient I-S axis as a fraction of the scan's extent.
double height_fraction(const Float& image, const Float::PointType& p) {
  const auto size = image.GetLargestPossibleRegion().GetSize();
  double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
  for (int corner = 0; corner < 8; ++corner) {
    Index k;
    for (int i = 0; i < 3; ++i)
      k[i] = (corner >> i) & 1 ? static_cast<itk::IndexValueType>(size[i]) - 1 : 0;
    Float::PointType q;
    image.TransformIndexToPhysicalPoint(k, q);
    lo = std::min(lo, q[2]);
    hi = std::max(hi, q[2]);
  }
  return hi > lo ? (p[2] - lo) / (hi - lo) : 0.5;
}

}  // namespace

std::optional<AutoSeed> find_bladder_seed(const ScanImage& image, const AutoSeedParams& p) {
  const auto& s = image.GetSpacing();
  const bool coarsen = std::min({s[0], s[1], s[2]}) < p.coarse_spacing_mm * 0.999;
  Float::Pointer coarse = coarsen ? resample_isotropic(image, p.coarse_spacing_mm, p.outside)
                                  : Float::Pointer(const_cast<Float*>(&image));
  auto smooth = gaussian(*coarse, p.smoothing_mm);
  auto cores = erode(*threshold(*smooth, p.lower, p.upper), p.core_erosion_mm);
  auto depth = signed_distance(*cores);
  auto cc = itk::ConnectedComponentImageFilter<Mask, LabelMap>::New();
  cc->SetInput(cores);
  cc->Update();
  const LabelMap& labels = *cc->GetOutput();
  std::vector<Core> found(cc->GetObjectCount() + 1);
  const auto size = labels.GetLargestPossibleRegion().GetSize();
  itk::ImageRegionConstIteratorWithIndex<LabelMap> it(&labels, labels.GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it) {
    const auto l = it.Get();
    if (!l) continue;
    Core& c = found[l];
    const Index k = it.GetIndex();
    Float::PointType q;
    labels.TransformIndexToPhysicalPoint(k, q);
    ++c.voxels;
    for (int i = 0; i < 3; ++i) {
      c.sum[i] += q[i];
      if (k[i] == 0 || k[i] + 1 == static_cast<itk::IndexValueType>(size[i]))
        c.touches_border = true;
    }
    const float d = depth->GetPixel(k);
    if (d < c.best_depth) c.best_depth = d, c.deepest = k;
  }
  std::optional<AutoSeed> best;
  nlohmann::json candidates = nlohmann::json::array();
  const double vml = voxel_ml(labels);
  for (std::size_t l = 1; l < found.size(); ++l) {
    const Core& c = found[l];
    const double ml = c.voxels * vml;
    if (ml < p.min_core_ml) continue;
    Float::PointType centroid;
    for (int i = 0; i < 3; ++i) centroid[i] = c.sum[i] / c.voxels;
    const double height = height_fraction(*coarse, centroid);
    const bool eligible = !c.touches_border && height <= p.max_height_fraction;
    candidates.push_back({{"core_ml", ml},
                          {"centroid_mm", {centroid[0], centroid[1], centroid[2]}},
                          {"height_fraction", height},
                          {"touches_border", c.touches_border},
                          {"eligible", eligible}});
    if (!eligible || (best && best->core_ml >= ml)) continue;
    AutoSeed a;
    Float::PointType q;
    labels.TransformIndexToPhysicalPoint(c.deepest, q);
    a.seed_mm = {q[0], q[1], q[2]};
    a.core_ml = ml;
    best = a;
  }
  if (best) best->candidates = candidates;
  return best;
}

}  // namespace vesica::segment
