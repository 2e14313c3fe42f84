#include "vesica/segment/DicomSeriesWriter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <vector>

#include <gdcmAttribute.h>
#include <gdcmReader.h>
#include <gdcmUIDGenerator.h>
#include <gdcmWriter.h>
#include <itkCastImageFilter.h>
#include <itkGDCMImageIO.h>
#include <itkImageSeriesWriter.h>
#include <itkMetaDataObject.h>

#include "vesica/core/Error.h"

namespace vesica::segment {
namespace {

using StoredImage = itk::Image<short, 3>;
using SliceImage = itk::Image<short, 2>;
constexpr double kRescaleIntercept = -1024.0;  // stored = HU + 1024, as many scanners do

// Values rounded to the integers a series stores: HU within the 12-bit CT range, or
// non-negative MR signal within the signed 16-bit range.
StoredImage::Pointer rounded(const ScanImage& image, Modality modality) {
  const double lo = modality == Modality::CT ? -1024.0 : 0.0;
  const double hi = modality == Modality::CT ? 3071.0 : 32767.0;
  auto out = StoredImage::New();
  out->CopyInformation(&image);
  out->SetRegions(image.GetLargestPossibleRegion());
  out->Allocate();
  const float* in = image.GetBufferPointer();
  short* dst = out->GetBufferPointer();
  const std::size_t n = image.GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t i = 0; i < n; ++i)
    dst[i] = static_cast<short>(std::clamp(std::round(static_cast<double>(in[i])), lo, hi));
  return out;
}

// GDCM writes an MR slice's SpacingBetweenSlices from the spacing of the 2-D image it is
// given (always 1 mm), over the value in the dictionary; so the true one is set after.
void set_spacing_between_slices(const std::vector<std::string>& files, double spacing_mm) {
  for (const auto& f : files) {
    gdcm::Reader reader;
    reader.SetFileName(f.c_str());
    if (!reader.Read()) fail(f, "cannot read back the DICOM file just written");
    gdcm::Attribute<0x0018, 0x0088> at;
    at.SetValue(spacing_mm);
    reader.GetFile().GetDataSet().Replace(at.GetAsDataElement());
    gdcm::Writer writer;
    writer.SetFileName(f.c_str());
    writer.SetFile(reader.GetFile());
    if (!writer.Write()) fail(f, "cannot write DICOM file");
  }
}

}  // namespace

std::string dicom_decimals(std::initializer_list<double> values) {
  std::ostringstream s;
  s.precision(10);
  bool first = true;
  for (double v : values) {
    if (!first) s << '\\';
    // Tiny values would print in scientific notation; DICOM DS accepts it but keep it tidy.
    s << (std::abs(v) < 1e-9 ? 0.0 : v);
    first = false;
  }
  return s.str();
}

DicomSeriesInfo write_dicom_series(const ScanImage& image, const std::filesystem::path& dir,
                                   const std::string& series_description) {
  DicomSeriesHeader header;
  header.series_description = series_description;
  return write_dicom_series(image, dir, header);
}

DicomSeriesInfo write_dicom_series(const ScanImage& image, const std::filesystem::path& dir,
                                   const DicomSeriesHeader& header) {
  std::filesystem::create_directories(dir);
  gdcm::UIDGenerator uids;
  DicomSeriesInfo info;
  info.study_uid = uids.Generate();
  info.series_uid = uids.Generate();
  const bool ct = header.modality == Modality::CT;
  const auto stored = rounded(image, header.modality);
  const auto size = image.GetLargestPossibleRegion().GetSize();
  const auto& d = image.GetDirection();
  const auto& s = image.GetSpacing();
  info.slice_count = static_cast<int>(size[2]);

  auto io = itk::GDCMImageIO::New();
  io->KeepOriginalUIDOn();  // use our UIDs, not fresh ones per file
  using Writer = itk::ImageSeriesWriter<StoredImage, SliceImage>;
  Writer::DictionaryArrayType dictionaries;
  std::vector<itk::MetaDataDictionary> storage(size[2]);
  std::vector<std::string> names;
  for (itk::SizeValueType k = 0; k < size[2]; ++k) {
    auto& dict = storage[k];
    auto set = [&dict](const std::string& tag, const std::string& value) {
      itk::EncapsulateMetaData<std::string>(dict, tag, value);
    };
    StoredImage::PointType position;
    stored->TransformIndexToPhysicalPoint({{0, 0, static_cast<itk::IndexValueType>(k)}}, position);
    if (ct) {
      set("0010|0010", "VESICA^PHANTOM");  // placeholder only; no real patient data
      set("0010|0020", "PHANTOM");
      set("0008|0016", "1.2.840.10008.5.1.4.1.1.2");  // CT Image Storage
      set("0028|1052", dicom_decimals({kRescaleIntercept}));
      set("0028|1053", "1");
      set("0028|1054", "HU");
    } else {
      set("0008|0016", "1.2.840.10008.5.1.4.1.1.4");  // MR Image Storage
    }
    set("0008|0060", modality_name(header.modality));
    set("0028|0004", "MONOCHROME2");
    set("0020|000d", info.study_uid);
    set("0020|000e", info.series_uid);
    set("0008|0018", uids.Generate());
    set("0008|103e", header.series_description);
    set("0020|0011", "1");
    set("0020|0013", std::to_string(k + 1));
    set("0020|0032", dicom_decimals({position[0], position[1], position[2]}));
    set("0020|0037", dicom_decimals({d(0, 0), d(1, 0), d(2, 0), d(0, 1), d(1, 1), d(2, 1)}));
    set("0028|0030", dicom_decimals({s[1], s[0]}));  // row spacing \ column spacing
    set("0018|0050", dicom_decimals({s[2]}));
    for (const auto& [tag, value] : header.attributes) set(tag, value);
    dictionaries.push_back(&dict);
    char name[32];
    std::snprintf(name, sizeof name, "slice_%04lu.dcm", static_cast<unsigned long>(k + 1));
    names.push_back((dir / name).string());
  }
  auto writer = Writer::New();
  writer->SetInput(stored);
  writer->SetImageIO(io);
  writer->SetFileNames(names);
  writer->SetMetaDataDictionaryArray(&dictionaries);
  try {
    writer->Update();
  } catch (const itk::ExceptionObject&) {
    fail(dir.string(), "cannot write DICOM series");
  }
  if (!ct) set_spacing_between_slices(names, s[2]);
  return info;
}

}  // namespace vesica::segment
