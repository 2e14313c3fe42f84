#include "vesica/segment/VolumeReader.h"

#include <itkImageFileReader.h>
#include <itkImageFileWriter.h>
#include <itkMetaImageIO.h>
#include <itkNiftiImageIO.h>
#include <itkNrrdImageIO.h>

#include "vesica/core/Error.h"
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

}  // namespace

Volume read_volume(const std::filesystem::path& input, const std::string& series_uid) {
  namespace fs = std::filesystem;
  if (!fs::exists(input)) fail(input.string(), "does not exist");
  Volume v;
  if (fs::is_directory(input)) {
    const auto all = scan_dicom_folder(input);
    const auto& series = choose_series(all, series_uid, input);
    v.image = read_dicom_series(series, input);
    v.series_uid = series.uid;
    v.modality = series.modality;
    v.format = "dicom";
    return v;
  }
  v.format = format_of(input);
  if (v.format.empty())
    fail(input.string(), "unsupported input format",
         "give a DICOM folder or a .nii/.nii.gz/.nrrd/.mha volume");
  auto reader = itk::ImageFileReader<CtImage>::New();
  reader->SetFileName(input.string());
  reader->SetImageIO(io_for(v.format));
  try {
    reader->Update();
  } catch (const itk::ExceptionObject& e) {
    fail(input.string(), "cannot read " + v.format + " volume (corrupt or truncated file)");
  }
  v.image = reader->GetOutput();
  v.image->DisconnectPipeline();
  const auto size = v.image->GetLargestPossibleRegion().GetSize();
  if (size[0] < 2 || size[1] < 2 || size[2] < 2)
    fail(input.string(), "is not a 3-D volume (fewer than 2 voxels along an axis)");
  return v;
}

void write_label(const LabelImage& label, const std::filesystem::path& path) {
  auto writer = itk::ImageFileWriter<LabelImage>::New();
  writer->SetInput(&label);
  writer->SetFileName(path.string());
  writer->SetImageIO(io_for(format_of(path)));
  writer->UseCompressionOn();
  try {
    writer->Update();
  } catch (const itk::ExceptionObject& e) {
    fail(path.string(), std::string("cannot write label map: ") + e.GetDescription());
  }
}

}  // namespace vesica::segment
