#include "vesica/segment/LabelStatistics.h"

#include <algorithm>
#include <limits>

#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkNearestNeighborInterpolateImageFunction.h>
#include <itkResampleImageFilter.h>

#include "vesica/core/Error.h"
#include "vesica/core/Units.h"

namespace vesica::segment {

LabelStatistics label_statistics(const LabelImage& label) {
  LabelStatistics s;
  s.bbox_min_mm.fill(std::numeric_limits<double>::max());
  s.bbox_max_mm.fill(std::numeric_limits<double>::lowest());
  std::array<double, 3> sum{};
  itk::ImageRegionConstIteratorWithIndex<LabelImage> it(&label, label.GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it) {
    if (!it.Get()) continue;
    LabelImage::PointType p;
    label.TransformIndexToPhysicalPoint(it.GetIndex(), p);
    ++s.voxel_count;
    for (int i = 0; i < 3; ++i) {
      sum[i] += p[i];
      s.bbox_min_mm[i] = std::min(s.bbox_min_mm[i], p[i]);
      s.bbox_max_mm[i] = std::max(s.bbox_max_mm[i], p[i]);
    }
  }
  const auto& sp = label.GetSpacing();
  s.volume_ml = units::ml_from_mm3(static_cast<double>(s.voxel_count) * sp[0] * sp[1] * sp[2]);
  if (s.voxel_count == 0) {
    s.bbox_min_mm.fill(0);
    s.bbox_max_mm.fill(0);
    return s;
  }
  for (int i = 0; i < 3; ++i) s.centroid_mm[i] = sum[i] / static_cast<double>(s.voxel_count);
  return s;
}

double dice(const LabelImage& a, const LabelImage& b) {
  if (a.GetLargestPossibleRegion() != b.GetLargestPossibleRegion())
    throw Error("label", "Dice needs two labels on the same grid");
  const std::size_t n = a.GetLargestPossibleRegion().GetNumberOfPixels();
  const auto* pa = a.GetBufferPointer();
  const auto* pb = b.GetBufferPointer();
  std::uint64_t both = 0, na = 0, nb = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool ia = pa[i] != 0, ib = pb[i] != 0;
    na += ia;
    nb += ib;
    both += ia && ib;
  }
  return na + nb == 0 ? 1.0 : 2.0 * static_cast<double>(both) / static_cast<double>(na + nb);
}

LabelImage::Pointer resample_label_like(const LabelImage& label, const LabelImage& like) {
  using Resample = itk::ResampleImageFilter<LabelImage, LabelImage>;
  auto resample = Resample::New();
  resample->SetInput(&label);
  resample->SetInterpolator(
      itk::NearestNeighborInterpolateImageFunction<LabelImage, double>::New());
  resample->SetOutputParametersFromImage(&like);
  resample->SetDefaultPixelValue(0);
  resample->Update();
  return resample->GetOutput();
}

}  // namespace vesica::segment
