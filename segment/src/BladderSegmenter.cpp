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

#include "ImageOps.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Units.h"
#include "vesica/segment/AutoSeed.h"

namespace vesica::segment {
namespace {

using namespace ops;

constexpr double kCoarseSpacingMm = 4.0;    // grid of the quick bounding pass
constexpr double kCoarseSmoothingMm = 2.0;  // Gaussian sigma of the quick pass
constexpr double kBoxMarginMm = 20.0;       // the fine steps may reach this far beyond it
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

// Where the bladder can be: a quick coarse pass (4 mm grid, Gaussian smoothing, the
// window, the opening) around the seed gives a box, grown by a margin, that bounds the
// expensive fine steps. Falls back to the whole region of interest.
Float::RegionType bladder_box(const Float& ct, const Float::PointType& seed,
                              const SegmentParams& p) {
  const auto around = region_around(ct, seed, p.roi_radius_mm);
  auto coarse =
      resample_isotropic(*crop_region(ct, around), std::max(p.work_spacing_mm, kCoarseSpacingMm));
  auto window = threshold(*gaussian(*coarse, kCoarseSmoothingMm), p.lower_hu, p.upper_hu);
  auto core = erode(*window, p.opening_mm);
  Index seed_index;
  coarse->TransformPhysicalPointToIndex(seed, seed_index);
  const auto start = nearest_inside(*core, seed_index, p.seed_search_mm + p.opening_mm);
  if (!start) return around;
  auto region = dilate(*component_at(*core, *start), p.opening_mm);
  auto box = region_covering(ct, *region, kBoxMarginMm);
  return box.Crop(around) ? box : around;
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
  if (p.seed_mm) {
    result.seed_mode = "manual";
    result.seed_mm = *p.seed_mm;
  } else {
    AutoSeedParams a;
    a.lower_hu = p.lower_hu;
    a.upper_hu = p.upper_hu;
    const auto found = find_bladder_seed(ct, a);
    clock.lap("auto_seed");
    if (!found)
      fail(source, "automatic seeding found no compact urine-density region in the pelvis",
           "give --seed x,y,z (LPS mm) inside the bladder");
    result.seed_mode = "auto";
    result.seed_mm = found->seed_mm;
    diag["auto_seed_candidates"] = found->candidates;
  }
  Float::PointType seed_point;
  for (int i = 0; i < 3; ++i) seed_point[i] = result.seed_mm[i];
  Index seed_index;
  if (!ct.TransformPhysicalPointToIndex(seed_point, seed_index)) {
    std::ostringstream m;
    m << "seed (" << seed_point[0] << ", " << seed_point[1] << ", " << seed_point[2]
      << ") mm lies outside the image";
    fail(source, m.str(), "give --seed in patient millimetres (LPS) inside the volume");
  }

  // 1-2: region of interest, working grid, smoothing.
  auto roi = crop_region(ct, bladder_box(ct, seed_point, p));
  diag["box_size"] = {roi->GetLargestPossibleRegion().GetSize()[0],
                      roi->GetLargestPossibleRegion().GetSize()[1],
                      roi->GetLargestPossibleRegion().GetSize()[2]};
  const auto& native = roi->GetSpacing();
  const bool coarsen = std::min({native[0], native[1], native[2]}) < p.work_spacing_mm * 0.999;
  Float::Pointer work = coarsen ? resample_isotropic(*roi, p.work_spacing_mm) : roi;
  clock.lap("crop");
  auto smoothed = anisotropic_diffusion(*work, p.diffusion_iterations, p.diffusion_conductance);
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
