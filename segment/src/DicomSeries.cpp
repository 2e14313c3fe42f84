#include "vesica/segment/DicomSeries.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include <gdcmExplicitDataElement.h>
#include <gdcmImageReader.h>
#include <gdcmImplicitDataElement.h>
#include <gdcmReader.h>
#include <gdcmScanner.h>
#include <gdcmTrace.h>
#include <itkGDCMImageIO.h>
#include <itkImageSeriesReader.h>

#include "DicomFileCheck.h"
#include "vesica/core/ContentHash.h"
#include "vesica/core/Error.h"
#include "vesica/io/VolumeHeaderCheck.h"

namespace vesica::segment {
namespace {

const gdcm::Tag kSeriesUid(0x0020, 0x000e), kModality(0x0008, 0x0060), kDescription(0x0008, 0x103e),
    kPosition(0x0020, 0x0032), kOrientation(0x0020, 0x0037), kRows(0x0028, 0x0010),
    kColumns(0x0028, 0x0011), kPixelSpacing(0x0028, 0x0030), kSamples(0x0028, 0x0002),
    kBitsAllocated(0x0028, 0x0100), kPixelRepresentation(0x0028, 0x0103), kEchoTime(0x0018, 0x0081),
    kSopClass(0x0008, 0x0016);

// CT and MR Image Storage: files of these classes always carry image geometry.
const char* const kCtImageStorage = "1.2.840.10008.5.1.4.1.1.2";
const char* const kMrImageStorage = "1.2.840.10008.5.1.4.1.1.4";

std::string trimmed(const char* value) {
  std::string s = value ? value : "";
  const auto b = s.find_first_not_of(" \0", 0, 2);
  const auto e = s.find_last_not_of(" \0", std::string::npos, 2);
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

// A backslash-separated decimal list; empty when any item is not a number.
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

bool all_finite(const std::vector<double>& v) {
  return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

std::array<double, 3> normal_of(const std::array<double, 6>& o) {
  return {o[1] * o[5] - o[2] * o[4], o[2] * o[3] - o[0] * o[5], o[0] * o[4] - o[1] * o[3]};
}

double along(const std::array<double, 3>& n, const std::array<double, 3>& p) {
  return n[0] * p[0] + n[1] * p[1] + n[2] * p[2];
}

// Row and column cosines of unit length and at right angles.
bool orthonormal(const std::array<double, 6>& o) {
  const double rr = o[0] * o[0] + o[1] * o[1] + o[2] * o[2];
  const double cc = o[3] * o[3] + o[4] * o[4] + o[5] * o[5];
  const double rc = o[0] * o[3] + o[1] * o[4] + o[2] * o[5];
  return std::abs(rr - 1) < 1e-3 && std::abs(cc - 1) < 1e-3 && std::abs(rc) < 1e-3;
}

std::string value(const gdcm::Scanner& scanner, const std::string& file, const gdcm::Tag& tag) {
  return trimmed(scanner.GetValue(file.c_str(), tag));
}

unsigned unsigned_value(const gdcm::Scanner& scanner, const std::string& file,
                        const gdcm::Tag& tag) {
  const auto v = numbers(value(scanner, file, tag));
  return v.size() == 1 && v[0] >= 0 && v[0] < 1e9 ? static_cast<unsigned>(v[0]) : 0;
}

// Records why a series cannot be read (the first problem found is kept).
void mark(DicomSeries& series, const std::string& file, const std::string& problem) {
  if (!series.problem.empty()) return;
  series.problem = problem;
  series.problem_file = file;
}

// One file's slice attributes into its series. Objects without image geometry (no
// position or orientation: reports, presentation states) are not slices and are skipped;
// geometry that is there but unusable marks the series.
void add_slice(const gdcm::Scanner& scanner, const std::string& file, DicomSeries& series) {
  const auto pos = numbers(value(scanner, file, kPosition));
  const auto ori = numbers(value(scanner, file, kOrientation));
  if (pos.empty() && ori.empty()) {
    const std::string sop = value(scanner, file, kSopClass);
    if (sop == kCtImageStorage || sop == kMrImageStorage)  // cut short before its geometry
      fail(file, "CT/MR image without ImagePositionPatient (truncated or corrupt file)",
           "export the series again");
    return;
  }
  if (pos.size() != 3 || ori.size() != 6 || !all_finite(pos) || !all_finite(ori))
    return mark(series, file, "ImagePositionPatient or ImageOrientationPatient is not finite");
  DicomSlice s;
  s.file = file;
  std::copy(pos.begin(), pos.end(), s.position_mm.begin());
  std::copy(ori.begin(), ori.end(), s.orientation.begin());
  if (!orthonormal(s.orientation))
    return mark(series, file, "ImageOrientationPatient is not two orthogonal unit vectors");
  s.columns_rows = {unsigned_value(scanner, file, kColumns), unsigned_value(scanner, file, kRows)};
  // PixelSpacing is (row spacing = between rows, column spacing = between columns).
  const auto spacing = numbers(value(scanner, file, kPixelSpacing));
  s.pixel_spacing_mm = spacing.size() == 2 ? std::array<double, 2>{spacing[1], spacing[0]}
                                           : std::array<double, 2>{1.0, 1.0};
  if (!all_finite(spacing) || !(s.pixel_spacing_mm[0] > 0) || !(s.pixel_spacing_mm[1] > 0))
    return mark(series, file, "PixelSpacing is not a positive number");
  if (s.columns_rows[0] == 0 || s.columns_rows[1] == 0)
    return mark(series, file, "Rows or Columns missing or zero");
  s.pixel_format = value(scanner, file, kSamples) + "/" + value(scanner, file, kBitsAllocated) +
                   "/" + value(scanner, file, kPixelRepresentation);
  const auto te = numbers(value(scanner, file, kEchoTime));
  if (te.size() == 1 && std::isfinite(te[0])) s.echo_time_ms = te[0];
  series.slices.push_back(std::move(s));
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

std::string echo_text(double te_ms) {
  if (te_ms < 0) return "none";
  std::ostringstream s;
  s << te_ms << " ms";
  return s.str();
}

// Every slice as the first: orientation, size, pixel spacing, pixel format, echo time. A
// multi-echo acquisition stored as one series (its echoes at the same positions) is
// named as such before the position checks would call it duplicate slices.
void check_slices_agree(const DicomSeries& series) {
  const DicomSlice& first = series.slices.front();
  for (const auto& s : series.slices) {
    if (std::abs(s.echo_time_ms - first.echo_time_ms) > 1e-3)
      fail(s.file,
           "the series mixes echo times (" + echo_text(first.echo_time_ms) + " and " +
               echo_text(s.echo_time_ms) + "): a multi-echo acquisition, not one image",
           "export one echo as its own series");
    for (int i = 0; i < 6; ++i)
      if (std::abs(s.orientation[i] - first.orientation[i]) > 1e-4)
        fail(s.file, "slice orientation differs from the rest of its series",
             "the series mixes orientations; choose another series");
    if (s.columns_rows != first.columns_rows)
      fail(s.file, "slice size differs from the rest of its series",
           "the series mixes image sizes; export it again");
    for (int i = 0; i < 2; ++i)
      if (std::abs(s.pixel_spacing_mm[i] - first.pixel_spacing_mm[i]) >
          1e-4 * first.pixel_spacing_mm[i])
        fail(s.file, "PixelSpacing differs from the rest of its series",
             "the series mixes pixel sizes; export it again");
    if (s.pixel_format != first.pixel_format)
      fail(s.file, "pixel format (samples/bits/sign) differs from the rest of its series",
           "export the series again");
  }
}

// Equal steps along the normal: no duplicate and no missing slice.
void check_even_spacing(const DicomSeries& series) {
  const auto n = normal_of(series.orientation);
  const double spacing = series.slice_spacing_mm();
  for (std::size_t k = 1; k < series.slices.size(); ++k) {
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
}

// Reads the pixels through ITK; names the file that fails to decode.
ScanImage::Pointer read_pixels(const std::vector<std::string>& names,
                               const std::filesystem::path& folder) {
  auto io = itk::GDCMImageIO::New();
  auto reader = itk::ImageSeriesReader<ScanImage>::New();
  reader->SetImageIO(io);
  reader->SetFileNames(names);
  try {
    reader->Update();
  } catch (const itk::ExceptionObject&) {
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
  ScanImage::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  return image;
}

}  // namespace

double DicomSeries::slice_spacing_mm() const {
  if (slices.size() < 2) return 0;
  const auto n = normal_of(orientation);
  return (along(n, slices.back().position_mm) - along(n, slices.front().position_mm)) /
         static_cast<double>(slices.size() - 1);
}

std::string series_key(const std::string& uid) {
  return sha256_hex("vesica series key v1:" + uid).substr(0, 16);
}

std::string DicomSeries::key() const {
  return series_key(uid);
}

// A series has a few thousand slices at most; a folder with far more files is not one.
constexpr std::size_t kMaxFolderFiles = 20000;

std::vector<DicomSeries> scan_dicom_folder(const std::filesystem::path& folder) {
  namespace fs = std::filesystem;
  if (!fs::is_directory(folder)) fail(folder.string(), "is not a folder");
  std::vector<std::string> files;
  std::map<std::string, bool> looks_dicom;
  for (const auto& e : fs::directory_iterator(folder)) {
    if (!e.is_regular_file()) continue;  // pipes and devices too: they never end
    if (files.size() == kMaxFolderFiles)
      fail(folder.string(), "holds more than " + std::to_string(kMaxFolderFiles) + " files",
           "give the folder of one series");
    const std::string f = e.path().string();
    // Throws for a DICOM file cut short in its header, before GDCM could abort on it.
    looks_dicom[f] = check_dicom_file(f) == DicomFileKind::Part10 || has_dicom_extension(f);
    files.push_back(f);
  }
  if (files.empty())
    fail(folder.string(), "folder is empty", "expected the DICOM files of one CT or MR series");
  std::sort(files.begin(), files.end());
  // GDCM prints its own multi-line complaints about odd files; vesica says one line.
  gdcm::Trace::WarningOff();
  gdcm::Trace::ErrorOff();
  gdcm::Trace::DebugOff();
  gdcm::Scanner scanner;
  for (const auto& tag :
       {kSeriesUid, kModality, kDescription, kPosition, kOrientation, kRows, kColumns,
        kPixelSpacing, kSamples, kBitsAllocated, kPixelRepresentation, kEchoTime, kSopClass})
    scanner.AddTag(tag);
  scanner.Scan(files);
  std::map<std::string, DicomSeries> by_uid;
  for (const auto& f : files) {
    if (!scanner.IsKey(f.c_str())) {
      // A DICOM slice that GDCM cannot parse must not silently shorten its series.
      if (looks_dicom[f]) fail(f, "unreadable DICOM file", "export the series again");
      continue;  // not DICOM
    }
    const std::string uid = value(scanner, f, kSeriesUid);
    auto& series = by_uid[uid];
    if (series.slices.empty() && series.problem.empty()) {
      series.uid = uid;
      series.modality = value(scanner, f, kModality);
      series.description = value(scanner, f, kDescription);
    }
    add_slice(scanner, f, series);
  }
  std::vector<DicomSeries> all;
  for (auto& [uid, series] : by_uid) {
    if (series.slices.empty() && series.problem.empty()) continue;  // no image geometry
    if (!series.slices.empty()) {
      const DicomSlice& first = series.slices.front();
      series.orientation = first.orientation;
      series.columns_rows = first.columns_rows;
      series.pixel_spacing_mm = first.pixel_spacing_mm;
      series.echo_time_ms = first.echo_time_ms;
      const auto n = normal_of(series.orientation);
      std::stable_sort(series.slices.begin(), series.slices.end(),
                       [&](const auto& a, const auto& b) {
                         return along(n, a.position_mm) < along(n, b.position_mm);
                       });
    }
    all.push_back(std::move(series));
  }
  if (all.empty())
    fail(folder.string(), "no DICOM image found in folder",
         "expected the DICOM files of a CT or MR series (or a .nii.gz/.nrrd/.mha volume)");
  return all;
}

const DicomSeries& choose_series(const std::vector<DicomSeries>& all, const std::string& wanted,
                                 const std::filesystem::path& folder) {
  if (!wanted.empty()) {
    for (const auto& s : all)
      if (s.key() == wanted || s.uid == wanted) return s;
    // The wanted value may be a UID: it is not echoed.
    fail(folder.string(), "no series matches --series",
         "see --list-series for the keys of the " + std::to_string(all.size()) +
             " series in this folder");
  }
  if (all.size() == 1) return all.front();
  fail(folder.string(), "folder holds " + std::to_string(all.size()) + " series",
       "choose one with --series KEY (see --list-series)");
}

ScanImage::Pointer read_dicom_series(const DicomSeries& series,
                                     const std::filesystem::path& folder) {
  if (!series.problem.empty()) fail(series.problem_file, series.problem, "export it again");
  check_slices_agree(series);
  check_even_spacing(series);
  // Rows x Columns x slices within the budget before GDCM or ITK allocates what they claim.
  io::require_voxel_budget(folder.string(), std::uint64_t{series.columns_rows[0]} *
                                                series.columns_rows[1] * series.slices.size());
  std::vector<std::string> names;
  for (const auto& s : series.slices) {
    check_complete(s.file);
    names.push_back(s.file);
  }
  ScanImage::Pointer image = read_pixels(names, folder);
  const auto size = image->GetLargestPossibleRegion().GetSize();
  if (size[0] != series.columns_rows[0] || size[1] != series.columns_rows[1] ||
      size[2] != series.slices.size())
    fail(folder.string(), "decoded pixel data does not match the slices' Rows and Columns");
  // Geometry from the tags we checked, so that it never depends on SliceThickness.
  const auto n = normal_of(series.orientation);
  ScanImage::SpacingType s;
  s[0] = series.pixel_spacing_mm[0];
  s[1] = series.pixel_spacing_mm[1];
  s[2] = series.slices.size() > 1 ? series.slice_spacing_mm() : 1.0;
  ScanImage::DirectionType d;
  for (int r = 0; r < 3; ++r) {
    d(r, 0) = series.orientation[r];
    d(r, 1) = series.orientation[3 + r];
    d(r, 2) = n[r];
  }
  ScanImage::PointType origin;
  for (int r = 0; r < 3; ++r) origin[r] = series.slices.front().position_mm[r];
  image->SetSpacing(s);
  image->SetDirection(d);
  image->SetOrigin(origin);
  return image;
}

}  // namespace vesica::segment
