#include "vesica/segment/DicomSeries.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include <gdcmExplicitDataElement.h>
#include <gdcmImageReader.h>
#include <gdcmImplicitDataElement.h>
#include <gdcmReader.h>
#include <gdcmScanner.h>
#include <gdcmTrace.h>
#include <itkGDCMImageIO.h>
#include <itkImageSeriesReader.h>

#include "vesica/core/Error.h"

namespace vesica::segment {
namespace {

const gdcm::Tag kSeriesUid(0x0020, 0x000e), kModality(0x0008, 0x0060), kDescription(0x0008, 0x103e),
    kPosition(0x0020, 0x0032), kOrientation(0x0020, 0x0037), kRows(0x0028, 0x0010),
    kColumns(0x0028, 0x0011), kPixelSpacing(0x0028, 0x0030);

std::string trimmed(const char* value) {
  std::string s = value ? value : "";
  const auto b = s.find_first_not_of(" \0", 0, 2);
  const auto e = s.find_last_not_of(" \0", std::string::npos, 2);
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::vector<double> numbers(const std::string& s) {
  std::vector<double> v;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, '\\')) {
    try {
      v.push_back(std::stod(item));
    } catch (const std::exception&) {
      return {};
    }
  }
  return v;
}

std::array<double, 3> normal_of(const std::array<double, 6>& o) {
  return {o[1] * o[5] - o[2] * o[4], o[2] * o[3] - o[0] * o[5], o[0] * o[4] - o[1] * o[3]};
}

double along(const std::array<double, 3>& n, const std::array<double, 3>& p) {
  return n[0] * p[0] + n[1] * p[1] + n[2] * p[2];
}

// Fills geometry of one file into its series; false when the file lacks image geometry.
bool add_slice(const gdcm::Scanner& scanner, const std::string& file, DicomSeries& series) {
  const auto pos = numbers(trimmed(scanner.GetValue(file.c_str(), kPosition)));
  const auto ori = numbers(trimmed(scanner.GetValue(file.c_str(), kOrientation)));
  if (pos.size() != 3 || ori.size() != 6) return false;
  const auto spacing = numbers(trimmed(scanner.GetValue(file.c_str(), kPixelSpacing)));
  std::array<double, 6> o;
  std::copy(ori.begin(), ori.end(), o.begin());
  if (series.slices.empty()) {
    series.orientation = o;
    series.columns_rows = {
        static_cast<unsigned>(std::atoi(trimmed(scanner.GetValue(file.c_str(), kColumns)).c_str())),
        static_cast<unsigned>(std::atoi(trimmed(scanner.GetValue(file.c_str(), kRows)).c_str()))};
    // PixelSpacing is (row spacing = between rows, column spacing = between columns).
    series.pixel_spacing_mm = spacing.size() == 2 ? std::array<double, 2>{spacing[1], spacing[0]}
                                                  : std::array<double, 2>{1.0, 1.0};
  } else {
    for (int i = 0; i < 6; ++i)
      if (std::abs(o[i] - series.orientation[i]) > 1e-4)
        fail(file, "slice orientation differs from the rest of series '" + series.uid + "'",
             "the series mixes orientations; choose another series");
  }
  series.slices.push_back({file, {pos[0], pos[1], pos[2]}});
  return true;
}

// GDCM reads a short pixel-data element without complaint (the missing part is left
// as zeros), so a truncated file is caught here: the file must be as long as its
// meta header plus the encoded length of its data set.
void check_complete(const std::string& file) {
  gdcm::Reader r;
  r.SetFileName(file.c_str());
  if (!r.Read()) fail(file, "truncated or corrupt DICOM file", "export the series again");
  const auto& header = r.GetFile().GetHeader();
  const auto& ds = r.GetFile().GetDataSet();
  const bool implicit =
      header.GetDataSetTransferSyntax().GetNegociatedType() == gdcm::TransferSyntax::Implicit;
  const std::uintmax_t encoded = static_cast<std::uintmax_t>(header.GetFullLength()) +
                                 (implicit ? ds.GetLength<gdcm::ImplicitDataElement>()
                                           : ds.GetLength<gdcm::ExplicitDataElement>());
  if (std::filesystem::file_size(file) < encoded)
    fail(file, "truncated DICOM file (pixel data shorter than declared)",
         "export the series again");
}

}  // namespace

double DicomSeries::slice_spacing_mm() const {
  if (slices.size() < 2) return 0;
  const auto n = normal_of(orientation);
  return (along(n, slices.back().position_mm) - along(n, slices.front().position_mm)) /
         static_cast<double>(slices.size() - 1);
}

std::vector<DicomSeries> scan_dicom_folder(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(folder)) fail(folder.string(), "is not a folder");
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(folder))
    if (e.is_regular_file()) files.push_back(e.path().string());
  if (files.empty())
    fail(folder.string(), "folder is empty", "expected the DICOM files of one CT series");
  std::sort(files.begin(), files.end());
  gdcm::Trace::WarningOff();
  gdcm::Scanner scanner;
  for (const auto& tag : {kSeriesUid, kModality, kDescription, kPosition, kOrientation, kRows,
                          kColumns, kPixelSpacing})
    scanner.AddTag(tag);
  scanner.Scan(files);
  std::map<std::string, DicomSeries> by_uid;
  for (const auto& f : files) {
    if (!scanner.IsKey(f.c_str())) continue;  // not DICOM (or unreadable header)
    const std::string uid = trimmed(scanner.GetValue(f.c_str(), kSeriesUid));
    auto& series = by_uid[uid];
    if (series.slices.empty()) {
      series.uid = uid;
      series.modality = trimmed(scanner.GetValue(f.c_str(), kModality));
      series.description = trimmed(scanner.GetValue(f.c_str(), kDescription));
    }
    add_slice(scanner, f, series);
  }
  std::vector<DicomSeries> all;
  for (auto& [uid, series] : by_uid) {
    if (series.slices.empty()) continue;  // DICOM objects without image geometry
    const auto n = normal_of(series.orientation);
    std::sort(series.slices.begin(), series.slices.end(), [&](const auto& a, const auto& b) {
      return along(n, a.position_mm) < along(n, b.position_mm);
    });
    all.push_back(std::move(series));
  }
  if (all.empty())
    fail(folder.string(), "no DICOM image found in folder",
         "expected the DICOM files of a CT series (or a .nii.gz/.nrrd/.mha volume)");
  return all;
}

const DicomSeries& choose_series(const std::vector<DicomSeries>& all, const std::string& uid,
                                 const std::filesystem::path& folder) {
  if (!uid.empty()) {
    for (const auto& s : all)
      if (s.uid == uid) return s;
    fail(folder.string(), "no series with SeriesInstanceUID " + uid,
         "see --list-series for the series in this folder");
  }
  if (all.size() == 1) return all.front();
  fail(folder.string(), "folder holds " + std::to_string(all.size()) + " series",
       "choose one with --series UID (see --list-series)");
}

CtImage::Pointer read_dicom_series(const DicomSeries& series, const std::filesystem::path& folder) {
  const auto n = normal_of(series.orientation);
  const double spacing = series.slice_spacing_mm();
  std::vector<std::string> names;
  for (std::size_t k = 0; k < series.slices.size(); ++k) {
    names.push_back(series.slices[k].file);
    if (k == 0) continue;
    const double step =
        along(n, series.slices[k].position_mm) - along(n, series.slices[k - 1].position_mm);
    if (step < 1e-3)
      fail(series.slices[k].file, "two slices at the same position",
           "the folder holds duplicate slices; remove them");
    if (std::abs(step - spacing) > 0.1 * spacing) {
      std::ostringstream m;
      m << "missing slice: " << step << " mm gap between this slice and the previous one ("
        << spacing << " mm average spacing)";
      fail(series.slices[k].file, m.str(), "the series is incomplete; export it again");
    }
  }
  for (const auto& f : names) check_complete(f);
  auto io = itk::GDCMImageIO::New();
  using Reader = itk::ImageSeriesReader<CtImage>;
  auto reader = Reader::New();
  reader->SetImageIO(io);
  reader->SetFileNames(names);
  try {
    reader->Update();
  } catch (const itk::ExceptionObject&) {
    // Name the file that fails to decode (truncated, unsupported compression).
    for (const auto& f : names) {
      gdcm::ImageReader r;
      r.SetFileName(f.c_str());
      std::vector<char> buffer;
      bool ok = r.Read();
      if (ok) {
        buffer.resize(r.GetImage().GetBufferLength());
        ok = r.GetImage().GetBuffer(buffer.data());
      }
      if (!ok) fail(f, "cannot decode DICOM pixel data (truncated or corrupt file)");
    }
    fail(folder.string(), "cannot read DICOM series pixel data");
  }
  CtImage::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  // Geometry from the tags we checked, so that it never depends on SliceThickness.
  CtImage::SpacingType s;
  s[0] = series.pixel_spacing_mm[0];
  s[1] = series.pixel_spacing_mm[1];
  s[2] = series.slices.size() > 1 ? spacing : 1.0;
  CtImage::DirectionType d;
  for (int r = 0; r < 3; ++r) {
    d(r, 0) = series.orientation[r];
    d(r, 1) = series.orientation[3 + r];
    d(r, 2) = n[r];
  }
  CtImage::PointType origin;
  for (int r = 0; r < 3; ++r) origin[r] = series.slices.front().position_mm[r];
  image->SetSpacing(s);
  image->SetDirection(d);
  image->SetOrigin(origin);
  return image;
}

}  // namespace vesica::segment
