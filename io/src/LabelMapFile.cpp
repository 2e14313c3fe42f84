// ITK translation unit (no Eigen here, see LabelMap.h).
#include <itkImage.h>
#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkImageIOBase.h>
#include <itkImageIOFactory.h>
#include <itkImageRegionConstIterator.h>
#include <itkImageRegionIterator.h>
#include <itkMetaDataObject.h>

#include <algorithm>
#include <cctype>
#include <cmath>

#include "LowerCase.h"
#include "SlicerHeader.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/io/LabelMap.h"
#include "vesica/io/SlicerSegmentation.h"
#include "vesica/io/VolumeHeaderCheck.h"

namespace vesica::io {
namespace {

using ReadImage = itk::Image<int, 3>;
using WriteImage = itk::Image<std::uint8_t, 3>;

bool ends_with(const std::string& name, const std::string& tail) {
  return name.size() >= tail.size() &&
         name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
}

void require_three_dimensions(const std::string& file) {
  itk::ImageIOBase::Pointer io =
      itk::ImageIOFactory::CreateImageIO(file.c_str(), itk::ImageIOFactory::FileModeEnum::ReadMode);
  if (!io) fail(file, "cannot read the label map", "expected .nii/.nii.gz/.nrrd/.mha/.seg.nrrd");
  try {
    io->SetFileName(file);
    io->ReadImageInformation();
  } catch (const itk::ExceptionObject&) {
    fail(file, "cannot read the label map header");
  }
  if (io->GetNumberOfDimensions() != 3)
    fail(file,
         "the label map has " + std::to_string(io->GetNumberOfDimensions()) +
             " dimensions, expected 3",
         "a Slicer segmentation with overlapping segments is 4-D: export it as a labelmap");
}

void require_finite_geometry(const LabelMap& map, const std::string& file) {
  for (int d = 0; d < 3; ++d)
    if (!(std::isfinite(map.spacing_mm[d]) && map.spacing_mm[d] > 0) ||
        !std::isfinite(map.origin_mm[d]))
      fail(file, "voxel spacing or origin is not finite and positive");
  for (double v : map.direction)
    if (!std::isfinite(v)) fail(file, "the image direction is not finite");
}

}  // namespace

std::size_t LabelMap::voxel_count() const {
  return static_cast<std::size_t>(std::count(voxels.begin(), voxels.end(), std::uint8_t{1}));
}

bool is_label_map_file(const std::filesystem::path& path) {
  const std::string name = detail::lower_case(path.filename().string());
  for (const char* ext : {".nii", ".nii.gz", ".nrrd", ".nhdr", ".mha", ".mhd"})
    if (ends_with(name, ext)) return true;
  return false;
}

LabelMap read_label_map(const std::filesystem::path& path, int label) {
  const std::string file = path.string();
  if (!std::filesystem::exists(path)) fail(file, "label map not found");
  check_volume_file(path);  // sizes and budget before ITK allocates what they claim
  require_three_dimensions(file);
  // A .seg.nrrd without segment keys was written by a tool that knows only NRRD (Slicer
  // reads such a file as one segment per label value): any non-zero voxel is inside.
  if (label == 0 && is_slicer_segmentation(path) && lists_segments(path))
    label = bladder_label_value(read_segments(path), file);
  auto reader = itk::ImageFileReader<ReadImage>::New();
  reader->SetFileName(file);
  try {
    reader->Update();
  } catch (const itk::ExceptionObject&) {
    fail(file, "cannot read the label map", "expected .nii/.nii.gz/.nrrd/.mha/.seg.nrrd");
  }
  const ReadImage* image = reader->GetOutput();
  const auto region = image->GetLargestPossibleRegion();
  LabelMap out;
  for (int d = 0; d < 3; ++d) {
    out.size[d] = static_cast<int>(region.GetSize()[d]);
    out.spacing_mm[d] = image->GetSpacing()[d];
    out.origin_mm[d] = image->GetOrigin()[d];
    for (int e = 0; e < 3; ++e) out.direction[3 * d + e] = image->GetDirection()(d, e);
  }
  require_finite_geometry(out, file);
  out.voxels.reserve(region.GetNumberOfPixels());
  for (itk::ImageRegionConstIterator<ReadImage> it(image, region); !it.IsAtEnd(); ++it) {
    const int v = it.Get();
    out.voxels.push_back((label == 0 ? v != 0 : v == label) ? 1 : 0);
  }
  return out;
}

void write_label_map(const LabelMap& map, const std::filesystem::path& path) {
  const std::string file = path.string();
  if (!is_label_map_file(path))
    fail(file, "unknown label map format", "use .nii.gz, .nii, .nrrd, .mha or .seg.nrrd");
  const std::size_t count = static_cast<std::size_t>(map.size[0]) * map.size[1] * map.size[2];
  if (map.voxels.size() != count)
    fail(file,
         std::to_string(map.voxels.size()) + " voxels for a grid of " + std::to_string(count));
  auto image = WriteImage::New();
  WriteImage::RegionType region;
  WriteImage::SpacingType spacing;
  WriteImage::PointType origin;
  WriteImage::DirectionType direction;
  for (int d = 0; d < 3; ++d) {
    region.SetSize(d, static_cast<itk::SizeValueType>(map.size[d]));
    spacing[d] = map.spacing_mm[d];
    origin[d] = map.origin_mm[d];
    for (int e = 0; e < 3; ++e) direction(d, e) = map.direction[3 * d + e];
  }
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate();
  std::size_t v = 0;
  for (itk::ImageRegionIterator<WriteImage> it(image, region); !it.IsAtEnd(); ++it)
    it.Set(map.voxels[v++]);
  if (is_slicer_segmentation(path))
    for (const auto& [key, value] : detail::slicer_header_keys(map))
      itk::EncapsulateMetaData<std::string>(image->GetMetaDataDictionary(), key, value);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    auto writer = itk::ImageFileWriter<WriteImage>::New();
    writer->SetInput(image);
    writer->SetFileName(tmp.string());
    writer->SetUseCompression(!ends_with(detail::lower_case(file), ".nii"));
    try {
      writer->Update();
    } catch (const itk::ExceptionObject& e) {
      fail(file, std::string("ITK could not write the label map: ") + e.GetDescription());
    }
  });
}

}  // namespace vesica::io
