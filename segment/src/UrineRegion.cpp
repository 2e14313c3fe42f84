#include "UrineRegion.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkResampleImageFilter.h>
#include <itkThresholdSegmentationLevelSetImageFilter.h>

#include "StepClock.h"
#include "vesica/core/Error.h"

namespace vesica::segment {
namespace {

using namespace ops;

constexpr double kCoarseSpacingMm = 4.0;    // grid of the quick bounding pass
constexpr double kCoarseSmoothingMm = 2.0;  // Gaussian sigma of the quick pass
constexpr double kBoxMarginMm = 20.0;       // the fine steps may reach this far beyond it
constexpr double kMaxAnisotropy = 1.2;      // voxel edge ratio processed as it is

// The partial-volume border: half way between the urine level inside the region and
// the level of its immediate surroundings, so that border voxels split evenly whatever
// the bladder touches (docs/physics.md §10.2).
void border_levels(const Float& smoothed, const Mask& region, const UrineWindow& w,
                   const SegmentParams& p, SegmentResult& r) {
  auto core = erode(region, p.shell_inner());
  r.urine_level = median_where(smoothed, count(*core) ? *core : region);
  auto outer = dilate(region, p.shell_outer());
  auto inner = dilate(region, p.shell_inner());
  auto* o = outer->GetBufferPointer();
  const auto* i = inner->GetBufferPointer();
  const std::size_t n = outer->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < n; ++k) o[k] = o[k] && !i[k];
  r.surroundings_level = percentile_where(smoothed, *outer, w.surroundings_percentile);
  if (std::isnan(r.surroundings_level)) r.surroundings_level = w.lower;
  // Never above the finding window's floor (the region must stay inside), never so low
  // that the partial volumes of darker neighbours join.
  r.border_level =
      std::clamp(0.5 * (r.urine_level + r.surroundings_level), r.urine_level - w.floor_gap,
                 std::min(w.lower, r.urine_level - w.min_gap));
}

// Level-set refinement: moves the border of the eroded region to where the smoothed
// image crosses the border level, with curvature resisting thin leaks.
Float::Pointer refine_level_set(const Float& smoothed, const Mask& region, double border_level,
                                const UrineWindow& w, const SegmentParams& p) {
  auto start = erode(region, smoothed.GetSpacing()[0]);
  if (count(*start) == 0) start = Mask::Pointer(const_cast<Mask*>(&region));
  auto phi0 = signed_distance(*start);
  auto ls = itk::ThresholdSegmentationLevelSetImageFilter<Float, Float>::New();
  ls->SetInput(phi0);
  ls->SetFeatureImage(&smoothed);
  ls->SetLowerThreshold(static_cast<float>(border_level));
  ls->SetUpperThreshold(static_cast<float>(w.upper));
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
Float::RegionType bladder_box(const Float& image, const Float::PointType& seed,
                              const UrineWindow& w, const SegmentParams& p) {
  const auto around = region_around(image, seed, p.roi_radius_mm);
  auto coarse = resample_isotropic(*crop_region(image, around),
                                   std::max(p.work_spacing_mm, kCoarseSpacingMm), w.outside);
  auto window = threshold(*gaussian(*coarse, kCoarseSmoothingMm), w.lower, w.upper);
  auto core = erode(*window, p.opening_mm);
  Index seed_index;
  coarse->TransformPhysicalPointToIndex(seed, seed_index);
  const auto start = nearest_inside(*core, seed_index, p.seed_search_mm + p.opening_mm);
  if (!start) return around;
  auto region = dilate(*component_at(*core, *start), p.opening_mm);
  auto box = region_covering(image, *region, kBoxMarginMm);
  return box.Crop(around) ? box : around;
}

std::string window_text(const UrineWindow& w) {
  std::ostringstream s;
  s << "the urine window [" << w.lower << ", ";
  if (w.upper < 1e30)
    s << w.upper;
  else
    s << "inf";
  s << "] (" << w.units << ") selects nothing near the seed";
  return s.str();
}

// Opening = erosion, component at the seed, dilation back inside the window; harder while
// the region is implausibly large (the leak guard).
Mask::Pointer opened_region(const Mask& window, const Index& seed, const UrineWindow& w,
                            const SegmentParams& p, const std::string& source,
                            nlohmann::json& diag) {
  Mask::Pointer region;
  for (double opening = p.opening_mm;; opening += 0.5 * p.opening_mm) {
    auto core = erode(window, opening);
    const auto start = nearest_inside(*core, seed, p.seed_search_mm + opening);
    if (!start) {
      if (opening == p.opening_mm)
        fail(source, window_text(w),
             "check --seed (LPS mm) and the window options; a volume file is read as CT "
             "unless --modality mr");
      break;
    }
    auto opened = dilate(*component_at(*core, *start), opening);
    auto* o = opened->GetBufferPointer();
    const auto* in = window.GetBufferPointer();
    const std::size_t n = opened->GetLargestPossibleRegion().GetNumberOfPixels();
    for (std::size_t i = 0; i < n; ++i) o[i] = o[i] && in[i];
    const double ml = count(*opened) * voxel_ml(*opened);
    diag["opening_steps"].push_back({{"opening_mm", opening}, {"volume_ml", ml}});
    region = opened;
    if (ml <= p.max_volume_ml || opening + 0.5 * p.opening_mm > p.max_opening_mm) break;
  }
  if (!region) fail(source, "no plausible bladder region near the seed");
  return largest_component(*region);
}

// The region-of-interest result pasted into a label on the input grid.
Mask::Pointer on_input_grid(const Mask& refined, const Float& image) {
  auto label = Mask::New();
  label->CopyInformation(&image);
  label->SetRegions(image.GetLargestPossibleRegion());
  label->Allocate();
  label->FillBuffer(0);
  itk::ImageRegionConstIteratorWithIndex<Mask> it(&refined, refined.GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it) {
    if (!it.Get()) continue;
    Float::PointType q;
    Index k;
    refined.TransformIndexToPhysicalPoint(it.GetIndex(), q);
    if (label->TransformPhysicalPointToIndex(q, k)) label->SetPixel(k, 1);
  }
  return label;
}

}  // namespace

void segment_urine_region(const Float& image, const Float::PointType& seed, const UrineWindow& w,
                          const SegmentParams& p, const std::string& source,
                          SegmentResult& result) {
  auto& diag = result.diagnostics;
  StepClock clock(diag["step_seconds"]);
  // 1-2: region of interest, working grid, smoothing.
  auto roi = crop_region(image, bladder_box(image, seed, w, p));
  const auto roi_size = roi->GetLargestPossibleRegion().GetSize();
  diag["box_size"] = {roi_size[0], roi_size[1], roi_size[2]};
  // Finer inputs are coarsened to the working grid; anisotropic ones (thick MR slices)
  // are brought to it too, so that the opening and the level set see round balls.
  const auto& native = roi->GetSpacing();
  const double finest = std::min({native[0], native[1], native[2]});
  const double coarsest = std::max({native[0], native[1], native[2]});
  const bool resample = finest < p.work_spacing_mm * 0.999 || coarsest > kMaxAnisotropy * finest;
  Float::Pointer work = resample ? resample_isotropic(*roi, p.work_spacing_mm, w.outside) : roi;
  clock.lap("crop");
  auto smoothed = anisotropic_diffusion(*work, p.diffusion_iterations, p.diffusion_conductance);
  clock.lap("diffusion");

  // 3-4: window, opening, component at the seed, leak guard.
  auto window = threshold(*smoothed, w.lower, w.upper);
  Index seed_work;
  smoothed->TransformPhysicalPointToIndex(seed, seed_work);
  auto region = opened_region(*window, seed_work, w, p, source, diag);
  diag["opened_volume_ml"] = count(*region) * voxel_ml(*region);
  clock.lap("opening");

  // 5: level-set refinement, holes, largest component.
  border_levels(*smoothed, *region, w, p, result);
  diag["urine_level"] = result.urine_level;
  diag["surroundings_level"] = result.surroundings_level;
  diag["border_level"] = result.border_level;
  auto phi = refine_level_set(*smoothed, *region, result.border_level, w, p);
  if (resample) {  // the level-set function back on the input grid: sub-voxel borders
    auto f = itk::ResampleImageFilter<Float, Float>::New();
    f->SetInput(phi);
    f->SetOutputParametersFromImage(roi);
    f->SetDefaultPixelValue(1e3f);
    f->Update();
    phi = f->GetOutput();
  }
  clock.lap("level_set");
  auto refined = largest_component(*fill_holes(*threshold(*phi, -1e30, 0.0)));
  diag["refined_volume_ml"] = count(*refined) * voxel_ml(*refined);
  result.label = on_input_grid(*refined, image);
  clock.lap("finish");
}

}  // namespace vesica::segment
