#include "vesica/segment/LabelStatistics.h"

#include <algorithm>
#include <limits>

#include <itkBinaryThresholdImageFilter.h>
#include <itkCastImageFilter.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkLinearInterpolateImageFunction.h>
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
  // Linear interpolation of the 0/1 label, then the 0.5 level: the border lands where
  // the labels' own voxel faces put it, which nearest neighbour would shift by up to half
  // a voxel.
  using Real = itk::Image<float, 3>;
  auto cast = itk::CastImageFilter<LabelImage, Real>::New();
  cast->SetInput(&label);
  auto resample = itk::ResampleImageFilter<Real, Real>::New();
  resample->SetInput(cast->GetOutput());
  resample->SetInterpolator(itk::LinearInterpolateImageFunction<Real, double>::New());
  resample->SetOutputParametersFromImage(&like);
  resample->SetDefaultPixelValue(0);
  auto level = itk::BinaryThresholdImageFilter<Real, LabelImage>::New();
  level->SetInput(resample->GetOutput());
  level->SetLowerThreshold(0.5f);
  level->SetInsideValue(1);
  level->SetOutsideValue(0);
  level->Update();
  return level->GetOutput();
}

}  // namespace vesica::segment
