// The only ITK translation unit of the surface stage.
#include "ItkLabelReader.h"

#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageRegionConstIterator.h>

#include "vesica/core/Error.h"

namespace vesica::surface::detail {

ItkLabel read_itk_label(const std::string& path, int label) {
  using Image = itk::Image<int, 3>;
  auto reader = itk::ImageFileReader<Image>::New();
  reader->SetFileName(path);
  try {
    reader->Update();
  } catch (const itk::ExceptionObject&) {
    fail(path, "cannot read the label map", "expected .nii/.nii.gz/.nrrd/.mha");
  }
  const Image* image = reader->GetOutput();
  const auto region = image->GetLargestPossibleRegion();
  ItkLabel out;
  for (int d = 0; d < 3; ++d) {
    out.size[d] = static_cast<int>(region.GetSize()[d]);
    out.spacing[d] = image->GetSpacing()[d];
    out.origin[d] = image->GetOrigin()[d];
    for (int e = 0; e < 3; ++e) out.direction[3 * d + e] = image->GetDirection()(d, e);
  }
  out.inside.reserve(region.GetNumberOfPixels());
  for (itk::ImageRegionConstIterator<Image> it(image, region); !it.IsAtEnd(); ++it) {
    const int v = it.Get();
    out.inside.push_back((label == 0 ? v != 0 : v == label) ? 1 : 0);
  }
  return out;
}

}  // namespace vesica::surface::detail
