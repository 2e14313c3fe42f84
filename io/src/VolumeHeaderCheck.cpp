#include "vesica/io/VolumeHeaderCheck.h"

#include <itkImageIOBase.h>
#include <itkMetaImageIO.h>
#include <itkNrrdImageIO.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <set>
#include <vector>

#include "LowerCase.h"
#include "NiftiCheck.h"
#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"

namespace fs = std::filesystem;

namespace vesica::io {
namespace {

// zlib packs a run of equal bytes at most about 1032 to 1.
constexpr double kMaxDeflateRatio = 1032.0;
constexpr std::size_t kMaxHeaderBytes = 64 * 1024;
constexpr unsigned kMaxComponents = 64;
// NrrdIO formats its parse errors, the offending value included, into a fixed buffer of
// 1025 bytes without a bound (a 30,000-digit "kinds:" aborts the process): a field line is
// refused above this length before ITK sees it. Real fields are a few dozen characters;
// NRRD's free-text "key:=value" pairs and comments are not parsed and not bounded here.
constexpr std::size_t kMaxFieldLineBytes = 512;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// What the header says about where its data lies and how it is encoded, read from its text
// (NRRD "encoding:" / "data file:", MetaImage "CompressedData" / "ElementDataFile").
struct DataPlacement {
  std::vector<fs::path> files;  // detached data files; empty: in the header's file
  bool compressed = false;      // gzip / zlib
  bool raw = true;              // raw bytes (else text, bzip2, ...: only the budget holds)
};

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// "key: value" (NRRD) or "Key = Value" (MetaImage) split at the first separator.
bool field(const std::string& line, char separator, std::string& key, std::string& value) {
  const auto at = line.find(separator);
  if (at == std::string::npos) return false;
  key = detail::lower_case(trimmed(line.substr(0, at)));
  value = trimmed(line.substr(at + 1));
  return true;
}

// The numbers of a header value, or nothing when one of them is not a finite number.
std::optional<std::vector<double>> numbers_of(const std::string& value) {
  std::vector<double> out;
  std::size_t at = 0;
  while (out.size() <= 64) {
    at = value.find_first_not_of(" \t", at);
    if (at == std::string::npos) return out;
    const std::size_t end = std::min(value.find_first_of(" \t", at), value.size());
    const std::string word = value.substr(at, end - at);
    char* stop = nullptr;
    const double x = std::strtod(word.c_str(), &stop);
    if (stop != word.c_str() + word.size() || !std::isfinite(x)) return std::nullopt;
    out.push_back(x);
    at = end;
  }
  return std::nullopt;
}

// MetaIO trusts its header's fields as it parses them: an NDims of 2^32 or a negative one
// hangs it, an unknown ElementType or a TransformMatrix of 1e308 aborts it (VNL). Each
// field ITK reads is checked here first; `dims` is the NDims read so far (0: not yet).
void check_metaimage_field(const std::string& file, const std::string& key,
                           const std::string& value, std::size_t& dims) {
  static const std::set<std::string> kElementTypes = {
      "met_char", "met_uchar", "met_short",     "met_ushort",     "met_int",   "met_uint",
      "met_long", "met_ulong", "met_long_long", "met_ulong_long", "met_float", "met_double"};
  static const std::set<std::string> kVectors = {"dimsize",
                                                 "elementspacing",
                                                 "offset",
                                                 "position",
                                                 "origin",
                                                 "transformmatrix",
                                                 "rotation",
                                                 "orientation",
                                                 "centerofrotation",
                                                 "elementsize",
                                                 "compresseddatasize",
                                                 "headersize",
                                                 "elementnumberofchannels",
                                                 "ndims"};
  const auto refuse = [&](const std::string& why) {
    fail(file, "MetaImage field " + key + " " + why, "the header is damaged");
  };
  if (key == "elementtype") {
    if (!kElementTypes.count(detail::lower_case(value))) refuse("names no voxel type");
    return;
  }
  if (!kVectors.count(key)) return;
  const auto numbers = numbers_of(value);
  if (!numbers || numbers->empty()) refuse("is not a list of finite numbers");
  const auto whole = [](double x) { return x >= 0 && x <= 1e15 && x == std::floor(x); };
  if (key == "ndims") {
    if (numbers->size() != 1 || (*numbers)[0] < 2 || (*numbers)[0] > 4) refuse("must be 2, 3 or 4");
    dims = static_cast<std::size_t>((*numbers)[0]);
  } else if (key == "dimsize" || key == "compresseddatasize" || key == "headersize" ||
             key == "elementnumberofchannels") {
    for (const double x : *numbers)
      if (!whole(x) && !(key == "headersize" && x == -1)) refuse("is not a count");
  } else if (key == "transformmatrix" || key == "rotation" || key == "orientation") {
    for (const double x : *numbers)
      if (std::abs(x) > 1.01) refuse("is no matrix of direction cosines");
  }
  const std::size_t want =
      key == "transformmatrix" || key == "rotation" || key == "orientation" ? dims * dims : dims;
  const bool per_axis = key != "ndims" && key != "compresseddatasize" && key != "headersize" &&
                        key != "elementnumberofchannels";
  if (per_axis && dims > 0 && numbers->size() != want)
    refuse("holds " + std::to_string(numbers->size()) + " numbers, not " + std::to_string(want));
}

// NrrdIO allocates the voxels its "sizes:" declare while ITK only asks for the header: the
// sizes are checked against the budget here first (the last three axes are space, any
// before them components).
void check_nrrd_sizes(const std::string& file, const std::string& value) {
  const auto sizes = numbers_of(value);
  if (!sizes || sizes->empty() || sizes->size() > 4)
    fail(file, "NRRD sizes \"" + single_line(value, 40) + "\" are not 1 to 4 counts",
         "the header is damaged");
  double space = 1.0, components = 1.0;
  for (std::size_t k = 0; k < sizes->size(); ++k) {
    const double n = (*sizes)[k];
    if (n < 1 || n != std::floor(n) || n > 1e15)
      fail(file, "NRRD sizes hold " + single_line(value, 40) + ", not counts",
           "the header is damaged");
    (k + 3 < sizes->size() ? components : space) *= n;
  }
  if (components > kMaxComponents)
    fail(file, "NRRD sizes declare " + std::to_string(static_cast<long long>(components)) +
                   " components per voxel, which cannot be right");
  require_voxel_budget(file,
                       space > 1e18 ? std::uint64_t{1} << 60 : static_cast<std::uint64_t>(space));
}

void detached(const fs::path& header, const std::string& name, DataPlacement& d) {
  const std::string lower = detail::lower_case(name);
  if (lower.rfind("list", 0) == 0 || name.find('%') != std::string::npos ||
      name.find(' ') != std::string::npos)
    fail(header.string(), "its data is a list or pattern of files, which vesica does not read",
         "save the volume as one file (.nrrd, .mha or .nii.gz)");
  if (lower != "local") d.files.push_back(header.parent_path() / name);
}

DataPlacement placement(const fs::path& path, bool nrrd) {
  std::ifstream in(path, std::ios::binary);
  std::string head(kMaxHeaderBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  DataPlacement d;
  std::size_t dims = 0;  // MetaImage NDims
  std::size_t start = 0;
  while (start < head.size()) {
    const auto end = std::min(head.find('\n', start), head.size());
    const std::string line = head.substr(start, end - start);
    start = end + 1;
    if (nrrd && trimmed(line).empty()) break;  // the blank line ends a NRRD header
    const bool free_text =
        line.rfind('#', 0) == 0 || (nrrd && line.find(":=") != std::string::npos);
    if (!free_text && line.size() > kMaxFieldLineBytes)
      fail(path.string(),
           "a header line of " + std::to_string(line.size()) + " characters (at most " +
               std::to_string(kMaxFieldLineBytes) + " in a field) cannot be right",
           "the header is damaged");
    std::string key, value;
    if (!field(line, nrrd ? ':' : '=', key, value)) continue;
    const std::string v = detail::lower_case(value);
    if (!nrrd) check_metaimage_field(path.string(), key, value, dims);
    if (nrrd && key == "sizes") check_nrrd_sizes(path.string(), value);
    if (nrrd && key == "encoding") {
      d.compressed = v == "gzip" || v == "gz";
      d.raw = v == "raw" || d.compressed;
    } else if (nrrd && (key == "data file" || key == "datafile")) {
      detached(path, value, d);
    } else if (!nrrd && key == "compresseddata") {
      d.compressed = v == "true";
    } else if (!nrrd && key == "elementdatafile") {
      detached(path, value, d);
      break;  // the last field of a MetaImage header
    }
  }
  return d;
}

// Dimensions, components and component size as ITK reads the header (what it allocates).
std::uint64_t declared_bytes(const fs::path& path, bool nrrd) {
  const std::string file = path.string();
  itk::ImageIOBase::Pointer io;
  if (nrrd)
    io = itk::NrrdImageIO::New().GetPointer();
  else
    io = itk::MetaImageIO::New().GetPointer();
  try {
    io->SetFileName(file);
    io->ReadImageInformation();
  } catch (const itk::ExceptionObject&) {
    fail(file, "not a readable volume header (truncated or corrupt file)");
  }
  const unsigned dims = io->GetNumberOfDimensions();
  if (dims < 2 || dims > 4) fail(file, "has " + std::to_string(dims) + " dimensions, expected 3");
  std::uint64_t voxels = 1;
  for (unsigned d = 0; d < dims; ++d) {
    const std::uint64_t n = io->GetDimensions(d);
    if (n == 0) fail(file, "has an axis of 0 voxels");
    if (n > kMaxVolumeVoxels) require_voxel_budget(file, n);  // before the product overflows
    voxels *= n;
    require_voxel_budget(file, voxels);
  }
  const unsigned components = io->GetNumberOfComponents();
  if (components == 0 || components > kMaxComponents)
    fail(file, std::to_string(components) + " components per voxel cannot be right");
  return voxels * components * io->GetComponentSize();
}

void check_itk_volume(const fs::path& path, bool nrrd) {
  const std::string file = path.string();
  const std::uintmax_t own = require_input_file(path, kMaxVolumeFileBytes, "volume");
  const DataPlacement d = placement(path, nrrd);
  std::uintmax_t data = d.files.empty() ? own : 0;
  for (const fs::path& f : d.files) data += require_input_file(f, kMaxVolumeFileBytes, "data file");
  const std::uint64_t bytes = declared_bytes(path, nrrd);
  const double limit =
      d.compressed ? kMaxDeflateRatio * static_cast<double>(data) : static_cast<double>(data);
  if (d.raw && static_cast<double>(bytes) > limit)
    fail(file,
         "its header declares " + std::to_string(bytes) + " bytes of voxels, more than its " +
             std::to_string(data) + " bytes of " + (d.compressed ? "compressed " : "") +
             "data can hold",
         "the file is truncated or its header is wrong");
}

}  // namespace

void require_voxel_budget(const std::string& file, std::uint64_t voxels) {
  if (voxels > kMaxVolumeVoxels)
    fail(file,
         "declares " + std::to_string(voxels) + " voxels, more than vesica reads (" +
             std::to_string(kMaxVolumeVoxels) + ", 512 x 512 x 1024)",
         "crop or resample the volume first");
}

void check_volume_file(const fs::path& path) {
  const std::string name = detail::lower_case(path.filename().string());
  if (ends_with(name, ".nii") || ends_with(name, ".nii.gz")) {
    require_input_file(path, kMaxVolumeFileBytes, "volume");
    detail::check_nifti_file(path);
  } else if (ends_with(name, ".nrrd") || ends_with(name, ".nhdr")) {
    check_itk_volume(path, true);
  } else if (ends_with(name, ".mha") || ends_with(name, ".mhd")) {
    check_itk_volume(path, false);
  }
}

}  // namespace vesica::io
