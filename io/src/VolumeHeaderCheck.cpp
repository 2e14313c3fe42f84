#include "vesica/io/VolumeHeaderCheck.h"

#include <itkImageIOBase.h>
#include <itkMetaImageIO.h>
#include <itkNrrdImageIO.h>

#include <algorithm>
#include <cctype>
#include <fstream>
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
  std::size_t start = 0;
  while (start < head.size()) {
    const auto end = std::min(head.find('\n', start), head.size());
    const std::string line = head.substr(start, end - start);
    start = end + 1;
    if (nrrd && trimmed(line).empty()) break;  // the blank line ends a NRRD header
    std::string key, value;
    if (!field(line, nrrd ? ':' : '=', key, value)) continue;
    const std::string v = detail::lower_case(value);
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
