#include "vesica/segment/VolumeReader.h"

#include <algorithm>
#include <cmath>

#include <itkImageFileReader.h>
#include <itkImageRegionConstIterator.h>
#include <itkMetaImageIO.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>
#include <vnl/algo/vnl_determinant.h>

#include "vesica/core/Error.h"
#include "vesica/io/VolumeHeaderCheck.h"
#include "vesica/segment/DicomSeries.h"

namespace vesica::segment {
namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string format_of(const std::filesystem::path& p) {
  const std::string name = p.filename().string();
  if (ends_with(name, ".nii") || ends_with(name, ".nii.gz")) return "nifti";
  if (ends_with(name, ".nrrd") || ends_with(name, ".nhdr")) return "nrrd";
  if (ends_with(name, ".mha") || ends_with(name, ".mhd")) return "metaimage";
  return {};
}

itk::ImageIOBase::Pointer io_for(const std::string& format) {
  if (format == "nifti") return itk::NiftiImageIO::New().GetPointer();
  if (format == "nrrd") return itk::NrrdImageIO::New().GetPointer();
  return itk::MetaImageIO::New().GetPointer();
}

// Finite, positive spacing; finite origin; a direction that is a rotation (or reflection):
// anything else would abort inside VNL at the first physical-point transform.
void check_geometry(const ScanImage& image, const std::string& source) {
  const auto& s = image.GetSpacing();
  const auto& o = image.GetOrigin();
  const auto& d = image.GetDirection();
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(s[i]) || !(s[i] > 0))
      fail(source, "voxel spacing is zero, negative or not a number");
    if (!std::isfinite(o[i])) fail(source, "image origin is not finite");
    for (int j = 0; j < 3; ++j)
      if (!std::isfinite(d(i, j))) fail(source, "image direction is not finite");
  }
  const double det = vnl_determinant(d.GetVnlMatrix().as_matrix());
  if (!(std::abs(std::abs(det) - 1.0) < 1e-3))
    fail(source, "image direction is not a rotation (determinant " + std::to_string(det) + ")");
}

// A NaN or infinite voxel would count as neither inside nor outside every window.
void check_values(const ScanImage& image, const std::string& source) {
  const float* v = image.GetBufferPointer();
  const std::size_t n = image.GetLargestPossibleRegion().GetNumberOfPixels();
  const auto bad = std::count_if(v, v + n, [](float x) { return !std::isfinite(x); });
  if (bad > 0)
    fail(source, std::to_string(bad) + " voxels are not finite numbers (NaN or infinite)",
         "the volume is corrupt; export it again");
}

// NIfTI, NRRD or MetaImage through ITK (NIfTI headers checked first).
void read_volume_file(const std::filesystem::path& input, Volume& v) {
  v.format = format_of(input);
  if (v.format.empty())
    fail(input.string(), "unsupported input format",
         "give a DICOM folder or a .nii/.nii.gz/.nrrd/.mha volume");
  io::check_volume_file(input);  // sizes and budget before ITK allocates what they claim
  auto reader = itk::ImageFileReader<ScanImage>::New();
  reader->SetFileName(input.string());
  reader->SetImageIO(io_for(v.format));
  try {
    reader->Update();
  } catch (const itk::ExceptionObject&) {
    fail(input.string(), "cannot read " + v.format + " volume (corrupt or truncated file)");
  }
  v.image = reader->GetOutput();
  v.image->DisconnectPipeline();
}

}  // namespace

Volume read_volume(const std::filesystem::path& input, const std::string& series) {
  namespace fs = std::filesystem;
  if (!fs::exists(input)) fail(input.string(), "does not exist");
  // ITK's warnings (odd headers, non-orthogonal directions) would add lines to stderr;
  // every problem that matters is reported as vesica's one line instead.
  itk::Object::GlobalWarningDisplayOff();
  Volume v;
  if (fs::is_directory(input)) {
    const auto all = scan_dicom_folder(input);
    const auto& chosen = choose_series(all, series, input);
    v.image = read_dicom_series(chosen, input);
    v.series_key = chosen.key();
    v.modality = chosen.modality;
    v.echo_time_ms = chosen.echo_time_ms;
    v.format = "dicom";
  } else {
    read_volume_file(input, v);
  }
  const auto size = v.image->GetLargestPossibleRegion().GetSize();
  if (size[0] < 2 || size[1] < 2 || size[2] < 2)
    fail(input.string(), "is not a 3-D volume (fewer than 2 voxels along an axis)");
  check_geometry(*v.image, input.string());
  check_values(*v.image, input.string());
  return v;
}
io::LabelMap to_label_map(const LabelImage& label) {
  io::LabelMap out;
  const auto region = label.GetLargestPossibleRegion();
  for (unsigned d = 0; d < 3; ++d) {
    out.size[d] = static_cast<int>(region.GetSize(d));
    out.spacing_mm[d] = label.GetSpacing()[d];
    out.origin_mm[d] = label.GetOrigin()[d];
    for (unsigned e = 0; e < 3; ++e) out.direction[3 * d + e] = label.GetDirection()(d, e);
  }
  out.voxels.reserve(region.GetNumberOfPixels());
  for (itk::ImageRegionConstIterator<LabelImage> it(&label, region); !it.IsAtEnd(); ++it)
    out.voxels.push_back(it.Get() != 0 ? 1 : 0);
  return out;
}

}  // namespace vesica::segment
