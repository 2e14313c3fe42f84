#include "vesica/segment/BladderSegmenter.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
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
#include <itkImageRegionIteratorWithIndex.h>
#include <itkLinearInterpolateImageFunction.h>
#include <itkRegionOfInterestImageFilter.h>
#include <itkRelabelComponentImageFilter.h>
#include <itkResampleImageFilter.h>
#include <itkSignedMaurerDistanceMapImageFilter.h>
#include <itkThresholdSegmentationLevelSetImageFilter.h>

#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Units.h"

namespace vesica::segment {
namespace {

using Float = CtImage;
using Mask = LabelImage;
using Index = Float::IndexType;
using LabelMap = itk::Image<unsigned int, 3>;
using Ball = itk::BinaryBallStructuringElement<Mask::PixelType, 3>;

double voxel_ml(const itk::ImageBase<3>& image) {
  const auto& s = image.GetSpacing();
  return units::ml_from_mm3(s[0] * s[1] * s[2]);
}

std::size_t count(const Mask& m) {
  const auto* p = m.GetBufferPointer();
  const std::size_t n = m.GetLargestPossibleRegion().GetNumberOfPixels();
  return static_cast<std::size_t>(std::count_if(p, p + n, [](auto v) { return v != 0; }));
}

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

Mask::Pointer erode(const Mask& m, double radius_mm) {
  auto f = itk::BinaryErodeImageFilter<Mask, Mask, Ball>::New();
  f->SetInput(&m);
  f->SetKernel(ball_mm(m, radius_mm));
  f->SetForegroundValue(1);
  f->SetBackgroundValue(0);
  f->Update();
  return f->GetOutput();
}

Mask::Pointer dilate(const Mask& m, double radius_mm) {
  auto f = itk::BinaryDilateImageFilter<Mask, Mask, Ball>::New();
  f->SetInput(&m);
  f->SetKernel(ball_mm(m, radius_mm));
  f->SetForegroundValue(1);
  f->SetBackgroundValue(0);
  f->Update();
  return f->GetOutput();
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

Float::Pointer crop(const Float& image, const Float::PointType& centre, double radius_mm) {
  const auto whole = image.GetLargestPossibleRegion();
  Index c;
  image.TransformPhysicalPointToIndex(centre, c);
  Float::RegionType region;
  for (int i = 0; i < 3; ++i) {
    const auto r = static_cast<itk::IndexValueType>(std::ceil(radius_mm / image.GetSpacing()[i]));
    region.SetIndex(i, c[i] - r);
    region.SetSize(i, static_cast<itk::SizeValueType>(2 * r + 1));
  }
  region.Crop(whole);
  auto f = itk::RegionOfInterestImageFilter<Float, Float>::New();
  f->SetInput(&image);
  f->SetRegionOfInterest(region);
  f->Update();
  return f->GetOutput();
}

// Resamples onto an isotropic grid of `spacing` covering the same physical box.
template <typename Image>
typename Image::Pointer resample_isotropic(const Image& image, double spacing) {
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
  f->SetDefaultPixelValue(-1000);
  f->Update();
  return f->GetOutput();
}

Float::Pointer anisotropic_diffusion(const Float& image, const SegmentParams& p) {
  auto f = itk::CurvatureAnisotropicDiffusionImageFilter<Float, Float>::New();
  f->SetInput(&image);
  const auto& s = image.GetSpacing();
  // Stable explicit step in 3-D is 1 / 2^(N+1) (ITK scales by the spacing itself).
  (void)s;
  f->SetTimeStep(0.0625);
  f->SetNumberOfIterations(static_cast<unsigned>(p.diffusion_iterations));
  f->SetConductanceParameter(p.diffusion_conductance);
  f->Update();
  return f->GetOutput();
}

// The mask voxel nearest to `seed` within `radius_mm`, if any.
std::optional<Index> nearest_inside(const Mask& m, const Index& seed, double radius_mm) {
  const auto& s = m.GetSpacing();
  Mask::RegionType box;
  for (int i = 0; i < 3; ++i) {
    const auto r = static_cast<itk::IndexValueType>(std::ceil(radius_mm / s[i]));
    box.SetIndex(i, seed[i] - r);
    box.SetSize(i, static_cast<itk::SizeValueType>(2 * r + 1));
  }
  if (!box.Crop(m.GetLargestPossibleRegion())) return std::nullopt;
  std::optional<Index> best;
  double best_d2 = radius_mm * radius_mm;
  itk::ImageRegionConstIteratorWithIndex<Mask> it(&m, box);
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

// Median of `image` where `where` is set (NaN when empty).
double median_where(const Float& image, const Mask& where) {
  std::vector<float> v;
  const auto* w = where.GetBufferPointer();
  const auto* x = image.GetBufferPointer();
  const std::size_t n = where.GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    if (w[i]) v.push_back(x[i]);
  if (v.empty()) return std::nan("");
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The partial-volume border: half way between the urine level inside the region and
// the level of its immediate surroundings, so that border voxels split evenly whether
// the bladder touches fat (phantom, lean patients) or wall and soft tissue.
void border_levels(const Float& smoothed, const Mask& region, const SegmentParams& p,
                   SegmentResult& r) {
  auto core = erode(region, p.shell_inner_mm);
  r.urine_hu = median_where(smoothed, count(*core) ? *core : region);
  auto outer = dilate(region, p.shell_outer_mm);
  auto inner = dilate(region, p.shell_inner_mm);
  auto* o = outer->GetBufferPointer();
  const auto* i = inner->GetBufferPointer();
  const std::size_t n = outer->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < n; ++k) o[k] = o[k] && !i[k];
  r.surroundings_hu = median_where(smoothed, *outer);
  if (std::isnan(r.surroundings_hu)) r.surroundings_hu = p.lower_hu;
  // Never above the finding window's floor (the region must stay inside), never so low
  // that fat-side partial volumes join.
  r.border_hu = std::clamp(0.5 * (r.urine_hu + r.surroundings_hu), r.urine_hu - 60.0,
                           std::min(p.lower_hu, r.urine_hu - 5.0));
}

// Level-set refinement: moves the border of the eroded region to where the smoothed
// image crosses the border level, with curvature resisting thin leaks.
Float::Pointer refine_level_set(const Float& smoothed, const Mask& region, double border_hu,
                                const SegmentParams& p) {
  auto start = erode(region, smoothed.GetSpacing()[0]);
  if (count(*start) == 0) start = Mask::Pointer(const_cast<Mask*>(&region));
  auto phi0 = signed_distance(*start);
  auto ls = itk::ThresholdSegmentationLevelSetImageFilter<Float, Float>::New();
  ls->SetInput(phi0);
  ls->SetFeatureImage(&smoothed);
  ls->SetLowerThreshold(static_cast<float>(border_hu));
  ls->SetUpperThreshold(static_cast<float>(p.upper_hu));
  ls->SetPropagationScaling(1.0);
  ls->SetCurvatureScaling(p.levelset_curvature);
  ls->SetMaximumRMSError(0.01);
  ls->SetNumberOfIterations(static_cast<unsigned>(p.levelset_iterations));
  ls->SetIsoSurfaceValue(0.0);
  ls->Update();
  Float::Pointer phi = ls->GetOutput();
  phi->DisconnectPipeline();
  // The border may move at most levelset_band_mm beyond the opened region.
  auto dist = signed_distance(region);
  auto* ph = phi->GetBufferPointer();
  const auto* d = dist->GetBufferPointer();
  const std::size_t n = phi->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    ph[i] = std::max(ph[i], static_cast<float>(d[i] - p.levelset_band_mm));
  return phi;
}

// Seconds per step into the diagnostics, to see where the time goes.
class StepClock {
 public:
  explicit StepClock(nlohmann::json& out) : out_(out) {}
  void lap(const std::string& step) {
    const auto now = std::chrono::steady_clock::now();
    out_[step] = std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  nlohmann::json& out_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

SegmentResult segment_bladder(const CtImage& ct, const SegmentParams& p,
                              const std::string& source) {
  SegmentResult result;
  auto& diag = result.diagnostics;
  StepClock clock(diag["step_seconds"]);
  if (!p.seed_mm) fail(source, "automatic seeding not implemented yet");
  result.seed_mode = "manual";
  result.seed_mm = *p.seed_mm;
  Float::PointType seed_point;
  for (int i = 0; i < 3; ++i) seed_point[i] = (*p.seed_mm)[i];
  Index seed_index;
  if (!ct.TransformPhysicalPointToIndex(seed_point, seed_index)) {
    std::ostringstream m;
    m << "seed (" << seed_point[0] << ", " << seed_point[1] << ", " << seed_point[2]
      << ") mm lies outside the image";
    fail(source, m.str(), "give --seed in patient millimetres (LPS) inside the volume");
  }

  // 1-2: region of interest, working grid, smoothing.
  auto roi = crop(ct, seed_point, p.roi_radius_mm);
  const auto& native = roi->GetSpacing();
  const bool coarsen = std::min({native[0], native[1], native[2]}) < p.work_spacing_mm * 0.999;
  Float::Pointer work = coarsen ? resample_isotropic(*roi, p.work_spacing_mm) : roi;
  clock.lap("crop");
  auto smoothed = anisotropic_diffusion(*work, p);
  clock.lap("diffusion");

  // 3: window, opening, component at the seed.
  auto window = threshold(*smoothed, p.lower_hu, p.upper_hu);
  Index seed_work;
  smoothed->TransformPhysicalPointToIndex(seed_point, seed_work);
  Mask::Pointer region;
  double opening = p.opening_mm;
  for (;; opening += 0.5 * p.opening_mm) {
    auto core = erode(*window, opening);
    const auto start = nearest_inside(*core, seed_work, p.seed_search_mm + opening);
    if (!start) {
      if (opening == p.opening_mm)
        fail(source,
             "the urine window [" + std::to_string(p.lower_hu) + ", " + std::to_string(p.upper_hu) +
                 "] HU selects nothing near the seed",
             "check --seed (LPS mm) or the window --lower-hu/--upper-hu");
      break;
    }
    // Opening = erosion, component, dilation back inside the window.
    auto opened = dilate(*component_at(*core, *start), opening);
    auto* o = opened->GetBufferPointer();
    const auto* w = window->GetBufferPointer();
    const std::size_t n = opened->GetLargestPossibleRegion().GetNumberOfPixels();
    for (std::size_t i = 0; i < n; ++i) o[i] = o[i] && w[i];
    const double ml = count(*opened) * voxel_ml(*opened);
    diag["opening_steps"].push_back({{"opening_mm", opening}, {"volume_ml", ml}});
    region = opened;
    if (ml <= p.max_volume_ml || opening + 0.5 * p.opening_mm > p.max_opening_mm) break;
  }
  if (!region) fail(source, "no plausible bladder region near the seed");
  region = largest_component(*region);
  diag["opened_volume_ml"] = count(*region) * voxel_ml(*region);
  clock.lap("opening");

  // 5: level-set refinement, holes, largest component.
  border_levels(*smoothed, *region, p, result);
  diag["urine_hu"] = result.urine_hu;
  diag["surroundings_hu"] = result.surroundings_hu;
  diag["border_hu"] = result.border_hu;
  auto phi = refine_level_set(*smoothed, *region, result.border_hu, p);
  if (coarsen) {
    auto f = itk::ResampleImageFilter<Float, Float>::New();
    f->SetInput(phi);
    f->SetOutputParametersFromImage(roi);
    f->SetDefaultPixelValue(1e3f);
    f->Update();
    phi = f->GetOutput();
  }
  clock.lap("level_set");
  auto refined = threshold(*phi, -1e30, 0.0);
  refined = largest_component(*fill_holes(*refined));
  diag["refined_volume_ml"] = count(*refined) * voxel_ml(*refined);

  // Paste the region-of-interest result into a label on the input grid.
  auto label = Mask::New();
  label->CopyInformation(&ct);
  label->SetRegions(ct.GetLargestPossibleRegion());
  label->Allocate();
  label->FillBuffer(0);
  itk::ImageRegionConstIteratorWithIndex<Mask> it(refined, refined->GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it) {
    if (!it.Get()) continue;
    Float::PointType q;
    Index k;
    refined->TransformIndexToPhysicalPoint(it.GetIndex(), q);
    if (label->TransformPhysicalPointToIndex(q, k)) label->SetPixel(k, 1);
  }
  result.label = label;
  clock.lap("finish");
  return result;
}

}  // namespace vesica::segment
