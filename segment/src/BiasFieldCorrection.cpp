#include "vesica/segment/BiasFieldCorrection.h"

#include <algorithm>
#include <cmath>

#include <itkBSplineControlPointImageFilter.h>
#include <itkImageRegionConstIteratorWithIndex.h>
#include <itkLinearInterpolateImageFunction.h>
#include <itkN4BiasFieldCorrectionImageFilter.h>
#include <itkNearestNeighborExtrapolateImageFunction.h>
#include <itkOtsuThresholdImageFilter.h>
#include <itkResampleImageFilter.h>
#include <itkVectorIndexSelectionCastImageFilter.h>

#include "ImageOps.h"
#include "vesica/core/Error.h"

namespace vesica::segment {
namespace {

using namespace ops;
using N4 = itk::N4BiasFieldCorrectionImageFilter<Float, Mask, Float>;

constexpr std::size_t kMinBodyVoxels = 64;  // fewer tissue voxels: nothing to correct
constexpr double kConvergence = 1e-3;       // N4's relative change of the field's spread

// Body mask: Otsu's threshold of the log signal. On a log scale air (a Rician floor of a
// few percent) stands far from every tissue, dark muscle and bright urine alike, so the
// two classes split at the body's edge.
Mask::Pointer body_mask(const Float& image) {
  auto log = Float::New();
  log->CopyInformation(&image);
  log->SetRegions(image.GetLargestPossibleRegion());
  log->Allocate();
  const float* in = image.GetBufferPointer();
  float* out = log->GetBufferPointer();
  const std::size_t n = image.GetLargestPossibleRegion().GetNumberOfPixels();
  const float floor = 1e-6f * std::max(1.0f, *std::max_element(in, in + n));
  for (std::size_t i = 0; i < n; ++i) out[i] = std::log(std::max(in[i], floor));
  auto otsu = itk::OtsuThresholdImageFilter<Float, Mask>::New();
  otsu->SetInput(log);
  otsu->Update();
  return threshold(*log, otsu->GetThreshold(), 1e30);
}

// The log field N4 fitted, evaluated on the grid it was fitted on.
Float::Pointer log_field_on(const N4& n4, const Float& grid) {
  using Lattice = N4::BiasFieldControlPointLatticeType;
  auto bspline = itk::BSplineControlPointImageFilter<Lattice, N4::ScalarImageType>::New();
  bspline->SetInput(n4.GetLogBiasFieldControlPointLattice());
  bspline->SetOrigin(grid.GetOrigin());
  bspline->SetSpacing(grid.GetSpacing());
  bspline->SetDirection(grid.GetDirection());
  bspline->SetSize(grid.GetLargestPossibleRegion().GetSize());
  bspline->SetSplineOrder(n4.GetSplineOrder());
  // The filter sizes its output only while generating it, so it runs before its output
  // is handed on (a downstream filter would otherwise take the lattice's size).
  bspline->Update();
  auto select = itk::VectorIndexSelectionCastImageFilter<N4::ScalarImageType, Float>::New();
  select->SetInput(bspline->GetOutput());
  select->SetIndex(0);
  select->Update();
  Float::Pointer field = select->GetOutput();
  field->DisconnectPipeline();
  field->CopyInformation(&grid);
  return field;
}

}  // namespace

BiasField estimate_bias_field(const Float& image, const MrParams& p, const std::string& source) {
  BiasField b;
  b.coarse = resample_isotropic(image, p.bias_spacing_mm, 0.0);
  b.body = body_mask(*b.coarse);
  if (count(*b.body) < kMinBodyVoxels)
    fail(source, "the MR image holds no tissue signal to correct", "check the input");
  auto n4 = N4::New();
  n4->SetInput(b.coarse);
  n4->SetMaskImage(b.body);
  N4::VariableSizeArrayType iterations(static_cast<unsigned>(p.bias_levels));
  iterations.Fill(static_cast<unsigned>(p.bias_iterations));
  n4->SetMaximumNumberOfIterations(iterations);
  n4->SetNumberOfFittingLevels(static_cast<unsigned>(p.bias_levels));
  n4->SetConvergenceThreshold(kConvergence);
  try {
    n4->Update();
  } catch (const itk::ExceptionObject&) {
    fail(source, "N4 bias-field correction failed on this image", "check the input");
  }
  b.log_bias = log_field_on(*n4, *b.coarse);
  return b;
}

Float::Pointer corrected_coarse(const BiasField& field) {
  return remove_bias(*field.coarse, *field.log_bias, 1.0);
}

Float::Pointer remove_bias(const Float& image, const Float& log_bias, double scale) {
  auto f = itk::ResampleImageFilter<Float, Float>::New();
  f->SetInput(&log_bias);
  f->SetInterpolator(itk::LinearInterpolateImageFunction<Float, double>::New());
  // The coarse grid's voxel centres stop half a coarse voxel inside the image's box.
  f->SetExtrapolator(itk::NearestNeighborExtrapolateImageFunction<Float, double>::New());
  f->SetOutputParametersFromImage(&image);
  f->Update();
  Float::Pointer out = f->GetOutput();
  out->DisconnectPipeline();
  float* o = out->GetBufferPointer();
  const float* in = image.GetBufferPointer();
  const std::size_t n = image.GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    o[i] = static_cast<float>(scale * in[i] * std::exp(-static_cast<double>(o[i])));
  return out;
}

}  // namespace vesica::segment
