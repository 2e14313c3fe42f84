#include "ImageOps.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <itkBinaryBallStructuringElement.h>
#include <itkBinaryDilateImageFilter.h>
#include <itkBinaryErodeImageFilter.h>
#include <itkBinaryFillholeImageFilter.h>
#include <itkBinaryThresholdImageFilter.h>
#include <itkConnectedComponentImageFilter.h>
#include <itkConnectedThresholdImageFilter.h>
#include <itkCurvatureAnisotropicDiffusionImageFilter.h>
#include <itkDiscreteGaussianImageFilter.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkRegionOfInterestImageFilter.h>
#include <itkRelabelComponentImageFilter.h>
#include <itkResampleImageFilter.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>

#include "vesica/core/Units.h"

namespace vesica::segment::ops {

using Ball = itk::BinaryBallStructuringElement<Mask::PixelType, 3>;

namespace {
Ball ball_mm(const itk::ImageBase<3>& image, double radius_mm) {
  Ball ball;
  Ball::SizeType r;
  for (int i = 0; i < 3; ++i)
    r[i] = std::max<itk::SizeValueType>(
        1, static_cast<itk::SizeValueType>(std::lround(radius_mm / image.GetSpacing()[i])));
  ball.SetRadius(r);
  ball.CreateStructuringElement();
  return ball;
}

}  // namespace

double voxel_ml(const itk::ImageBase<3>& image) {
  const auto& s = image.GetSpacing();
  return units::ml_from_mm3(s[0] * s[1] * s[2]);
}

std::size_t count(const Mask& m) {
  const auto* p = m.GetBufferPointer();
  const std::size_t n = m.GetLargestPossibleRegion().GetNumberOfPixels();
  return static_cast<std::size_t>(std::count_if(p, p + n, [](auto v) { return v != 0; }));
}

namespace {
// Erosion and dilation differ only in the ITK filter: a ball of radius_mm on the 0/1 mask.
template <template <class, class, class> class MorphologyFilter>
Mask::Pointer apply_ball(const Mask& m, double radius_mm) {
  auto f = MorphologyFilter<Mask, Mask, Ball>::New();
  f->SetInput(&m);
  f->SetKernel(ball_mm(m, radius_mm));
  f->SetForegroundValue(1);
  f->SetBackgroundValue(0);
  f->Update();
  return f->GetOutput();
}
}  // namespace

Mask::Pointer erode(const Mask& m, double radius_mm) {
  return apply_ball<itk::BinaryErodeImageFilter>(m, radius_mm);
}

Mask::Pointer dilate(const Mask& m, double radius_mm) {
  return apply_ball<itk::BinaryDilateImageFilter>(m, radius_mm);
}

Mask::Pointer threshold(const Float& image, double lower, double upper) {
  auto f = itk::BinaryThresholdImageFilter<Float, Mask>::New();
  f->SetInput(&image);
  f->SetLowerThreshold(static_cast<float>(lower));
  f->SetUpperThreshold(static_cast<float>(upper));
  f->SetInsideValue(1);
  f->SetOutsideValue(0);
  f->Update();
  return f->GetOutput();
}

// The connected part of `m` that contains `seed` (flood fill).
Mask::Pointer component_at(const Mask& m, const Index& seed) {
  auto f = itk::ConnectedThresholdImageFilter<Mask, Mask>::New();
  f->SetInput(&m);
  f->SetLower(1);
  f->SetUpper(1);
  f->SetReplaceValue(1);
  f->AddSeed(seed);
  f->Update();
  return f->GetOutput();
}

Mask::Pointer largest_component(const Mask& m) {
  auto cc = itk::ConnectedComponentImageFilter<Mask, LabelMap>::New();
  cc->SetInput(&m);
  auto relabel = itk::RelabelComponentImageFilter<LabelMap, LabelMap>::New();
  relabel->SetInput(cc->GetOutput());
  auto keep = itk::BinaryThresholdImageFilter<LabelMap, Mask>::New();
  keep->SetInput(relabel->GetOutput());
  keep->SetLowerThreshold(1);
  keep->SetUpperThreshold(1);
  keep->SetInsideValue(1);
  keep->SetOutsideValue(0);
  keep->Update();
  return keep->GetOutput();
}

Mask::Pointer fill_holes(const Mask& m) {
  auto f = itk::BinaryFillholeImageFilter<Mask>::New();
  f->SetInput(&m);
  f->SetForegroundValue(1);
  f->FullyConnectedOn();
  f->Update();
  return f->GetOutput();
}

Float::RegionType region_around(const Float& image, const Float::PointType& centre,
                                double radius_mm) {
  Index c;
  image.TransformPhysicalPointToIndex(centre, c);
  Float::RegionType region;
  for (int i = 0; i < 3; ++i) {
    const auto r = static_cast<itk::IndexValueType>(std::ceil(radius_mm / image.GetSpacing()[i]));
    region.SetIndex(i, c[i] - r);
    region.SetSize(i, static_cast<itk::SizeValueType>(2 * r + 1));
  }
  region.Crop(image.GetLargestPossibleRegion());
  return region;
}

// Resamples onto an isotropic grid of `spacing` covering the same physical box.
Float::Pointer resample_isotropic(const Float& image, double spacing, double outside) {
  using Image = Float;
  auto f = itk::ResampleImageFilter<Image, Image>::New();
  f->SetInput(&image);
  typename Image::SizeType size;
  typename Image::SpacingType s;
  typename Image::PointType origin;
  const auto in_size = image.GetLargestPossibleRegion().GetSize();
  for (int i = 0; i < 3; ++i) {
    const double extent = in_size[i] * image.GetSpacing()[i];
    size[i] = std::max<itk::SizeValueType>(1, std::lround(extent / spacing));
    s[i] = spacing;
  }
  // Same corner of the box: shift the first voxel centre by half the spacing change.
  Float::PointType first;
  image.TransformIndexToPhysicalPoint(image.GetLargestPossibleRegion().GetIndex(), first);
  for (int r = 0; r < 3; ++r) {
    origin[r] = first[r];
    for (int c = 0; c < 3; ++c)
      origin[r] += image.GetDirection()(r, c) * 0.5 * (spacing - image.GetSpacing()[c]);
  }
  f->SetSize(size);
  f->SetOutputSpacing(s);
  f->SetOutputOrigin(origin);
  f->SetOutputDirection(image.GetDirection());
  f->SetDefaultPixelValue(static_cast<float>(outside));
  f->Update();
  return f->GetOutput();
}

Float::Pointer anisotropic_diffusion(const Float& image, int iterations, double conductance) {
  auto f = itk::CurvatureAnisotropicDiffusionImageFilter<Float, Float>::New();
  f->SetInput(&image);
  const auto& s = image.GetSpacing();
  // Stable explicit step in 3-D is 1 / 2^(N+1) (ITK scales by the spacing itself).
  (void)s;
  f->SetTimeStep(0.0625);
  f->SetNumberOfIterations(static_cast<unsigned>(iterations));
  f->SetConductanceParameter(conductance);
  f->Update();
  return f->GetOutput();
}

std::optional<Float::RegionType> box_within(const itk::ImageBase<3>& image, const Index& seed,
                                            double radius_mm) {
  const auto& s = image.GetSpacing();
  Float::RegionType box;
  for (int i = 0; i < 3; ++i) {
    const auto r = static_cast<itk::IndexValueType>(std::ceil(radius_mm / s[i]));
    box.SetIndex(i, seed[i] - r);
    box.SetSize(i, static_cast<itk::SizeValueType>(2 * r + 1));
  }
  if (!box.Crop(image.GetLargestPossibleRegion())) return std::nullopt;
  return box;
}

// The mask voxel nearest to `seed` within `radius_mm`, if any.
std::optional<Index> nearest_inside(const Mask& m, const Index& seed, double radius_mm) {
  const auto& s = m.GetSpacing();
  const auto box = box_within(m, seed, radius_mm);
  if (!box) return std::nullopt;
  std::optional<Index> best;
  double best_d2 = radius_mm * radius_mm;
  itk::ImageRegionConstIteratorWithIndex<Mask> it(&m, *box);
  for (; !it.IsAtEnd(); ++it) {
    if (!it.Get()) continue;
    double d2 = 0;
    for (int i = 0; i < 3; ++i) d2 += std::pow((it.GetIndex()[i] - seed[i]) * s[i], 2);
    if (d2 <= best_d2) best_d2 = d2, best = it.GetIndex();
  }
  return best;
}

Float::Pointer signed_distance(const Mask& m) {
  auto f = itk::SignedMaurerDistanceMapImageFilter<Mask, Float>::New();
  f->SetInput(&m);
  f->SetInsideIsPositive(false);
  f->SetUseImageSpacing(true);
  f->SetSquaredDistance(false);
  f->Update();
  return f->GetOutput();
}

double percentile_where(const Float& image, const Mask& where, double percent) {
  std::vector<float> v;
  const auto* w = where.GetBufferPointer();
  const auto* x = image.GetBufferPointer();
  const std::size_t n = where.GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    if (w[i]) v.push_back(x[i]);
  if (v.empty()) return std::nan("");
  const auto k =
      std::min(v.size() - 1, static_cast<std::size_t>(std::clamp(percent, 0.0, 100.0) / 100.0 *
                                                      static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

double median_where(const Float& image, const Mask& where) {
  return percentile_where(image, where, 50.0);
}

Float::RegionType region_covering(const Float& image, const Mask& mask, double margin_mm) {
  // Bounding box of the mask in its own index space, then its corners in patient space.
  Index lo, hi;
  lo.Fill(std::numeric_limits<itk::IndexValueType>::max());
  hi.Fill(std::numeric_limits<itk::IndexValueType>::min());
  itk::ImageRegionConstIteratorWithIndex<Mask> it(&mask, mask.GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it)
    if (it.Get())
      for (int i = 0; i < 3; ++i) {
        lo[i] = std::min(lo[i], it.GetIndex()[i]);
        hi[i] = std::max(hi[i], it.GetIndex()[i]);
      }
  const Float::RegionType& region = image.GetLargestPossibleRegion();
  if (lo[0] > hi[0]) return region;  // empty mask: everything
  Index rlo, rhi;
  rlo.Fill(std::numeric_limits<itk::IndexValueType>::max());
  rhi.Fill(std::numeric_limits<itk::IndexValueType>::min());
  for (int corner = 0; corner < 8; ++corner) {
    itk::ContinuousIndex<double, 3> c;
    for (int i = 0; i < 3; ++i)
      c[i] = ((corner >> i) & 1) ? hi[i] + 0.5 + margin_mm / mask.GetSpacing()[i]
                                 : lo[i] - 0.5 - margin_mm / mask.GetSpacing()[i];
    Float::PointType p;
    mask.TransformContinuousIndexToPhysicalPoint(c, p);
    itk::ContinuousIndex<double, 3> k;
    image.TransformPhysicalPointToContinuousIndex(p, k);
    for (int i = 0; i < 3; ++i) {
      rlo[i] = std::min(rlo[i], static_cast<itk::IndexValueType>(std::floor(k[i])));
      rhi[i] = std::max(rhi[i], static_cast<itk::IndexValueType>(std::ceil(k[i])));
    }
  }
  Float::RegionType box;
  for (int i = 0; i < 3; ++i) {
    box.SetIndex(i, rlo[i]);
    box.SetSize(i, static_cast<itk::SizeValueType>(rhi[i] - rlo[i] + 1));
  }
  if (!box.Crop(region)) return region;
  return box;
}

Float::Pointer crop_region(const Float& image, const Float::RegionType& region) {
  auto f = itk::RegionOfInterestImageFilter<Float, Float>::New();
  f->SetInput(&image);
  f->SetRegionOfInterest(region);
  f->Update();
  return f->GetOutput();
}

Float::Pointer gaussian(const Float& image, double sigma_mm) {
  auto f = itk::DiscreteGaussianImageFilter<Float, Float>::New();
  f->SetInput(&image);
  f->SetVariance(sigma_mm * sigma_mm);
  f->SetUseImageSpacing(true);
  f->Update();
  return f->GetOutput();
}

}  // namespace vesica::segment::ops
