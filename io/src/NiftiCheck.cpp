#include "NiftiCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

#include <nifti1_io.h>

#include "vesica/core/Error.h"
#include "vesica/io/VolumeHeaderCheck.h"

namespace vesica::io::detail {
namespace {

constexpr double kMinDeterminant = 1e-12;  // of the sform's 3x3 part, mm^3

bool finite(std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

// What the file's data holds: its length from the file's start (decompressed for
// .nii.gz), up to `wanted`, and how many of its float voxels are NaN or infinite.
struct DataScan {
  std::uint64_t bytes = 0;
  std::uint64_t non_finite = 0;
};

template <class T>
std::uint64_t count_non_finite(const char* data, std::size_t n, bool swapped) {
  std::uint64_t bad = 0;
  for (std::size_t i = 0; i < n; ++i) {
    char raw[sizeof(T)];
    std::memcpy(raw, data + i * sizeof(T), sizeof(T));
    if (swapped) std::reverse(raw, raw + sizeof(T));
    T v;
    std::memcpy(&v, raw, sizeof(T));
    if (!std::isfinite(v)) ++bad;
  }
  return bad;
}

// ITK's reader turns NaN voxels into 0 (which CT would read as urine), so float data is
// checked here, as it streams past.
DataScan scan_data(const std::filesystem::path& file, const nifti_1_header& h, bool swapped,
                   std::uint64_t wanted) {
  const std::string name = file.string();
  znzFile f = znzopen(name.c_str(), "rb", nifti_is_gzfile(name.c_str()));
  DataScan scan;
  if (znz_isnull(f)) return scan;
  const auto start = static_cast<std::uint64_t>(h.vox_offset);
  const std::size_t element = h.datatype == DT_FLOAT32 ? 4 : h.datatype == DT_FLOAT64 ? 8 : 0;
  std::vector<char> buffer(1 << 20);
  std::vector<char> data;  // bytes past vox_offset not yet checked (a partial element)
  while (scan.bytes < wanted) {
    const std::size_t n = znzread(buffer.data(), 1, buffer.size(), f);
    if (n == 0) break;
    const std::uint64_t from = scan.bytes;
    scan.bytes += n;
    if (element == 0 || scan.bytes <= start) continue;
    const std::size_t skip = from < start ? static_cast<std::size_t>(start - from) : 0;
    data.insert(data.end(), buffer.begin() + static_cast<std::ptrdiff_t>(skip),
                buffer.begin() + static_cast<std::ptrdiff_t>(n));
    const std::size_t whole = data.size() / element;
    scan.non_finite += element == 4 ? count_non_finite<float>(data.data(), whole, swapped)
                                    : count_non_finite<double>(data.data(), whole, swapped);
    data.erase(data.begin(), data.begin() + static_cast<std::ptrdiff_t>(whole * element));
  }
  znzclose(f);
  return scan;
}

void check_geometry(const nifti_1_header& h, const std::string& file) {
  for (int i = 1; i <= 3; ++i)
    if (!finite({h.pixdim[i]}) || !(h.pixdim[i] > 0))
      fail(file, "voxel size (pixdim) is zero, negative or not a number",
           "the header lacks the voxel size; fix it in the exporting tool");
  if (h.qform_code > 0 && !finite({h.quatern_b, h.quatern_c, h.quatern_d, h.qoffset_x, h.qoffset_y,
                                   h.qoffset_z, h.pixdim[0]}))
    fail(file, "qform (orientation quaternion or offset) is not finite");
  if (h.sform_code > 0) {
    const float* r[3] = {h.srow_x, h.srow_y, h.srow_z};
    for (const float* row : r)
      if (!finite({row[0], row[1], row[2], row[3]})) fail(file, "sform affine is not finite");
    const double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                       r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                       r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    if (!(std::abs(det) > kMinDeterminant)) fail(file, "sform affine is singular");
  }
}

}  // namespace

void check_nifti_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  nifti_set_debug_level(0);  // its messages would break the one-line error rule
  int swapped = 0;
  std::unique_ptr<nifti_1_header, decltype(&std::free)> header(
      nifti_read_header(name.c_str(), &swapped, 1), &std::free);
  if (!header) fail(name, "not a readable NIfTI-1 header (truncated or corrupt file)");
  const nifti_1_header& h = *header;
  if (h.dim[0] < 3 || h.dim[0] > 7)
    fail(name, "is not a 3-D volume (" + std::to_string(h.dim[0]) + " dimensions)");
  std::uint64_t voxels = 1;
  for (int i = 1; i <= h.dim[0]; ++i) {
    if (h.dim[i] < 1) fail(name, "has an axis of " + std::to_string(h.dim[i]) + " voxels");
    if (i > 3 && h.dim[i] > 1)
      fail(name, "is a " + std::to_string(h.dim[0]) + "-D series, not one 3-D volume",
           "extract one volume first");
    voxels *= static_cast<std::uint64_t>(h.dim[i]);
  }
  require_voxel_budget(name, voxels);
  if (h.bitpix <= 0 || h.bitpix % 8 != 0) fail(name, "bits per voxel is not a whole byte count");
  check_geometry(h, name);
  if (!finite({h.scl_slope, h.scl_inter})) fail(name, "intensity scaling is not finite");
  if (!finite({h.vox_offset}) || h.vox_offset < 0) fail(name, "data offset is not valid");
  // ITK zero-fills what a short file lacks; the data must be there in full.
  const std::uint64_t needed =
      static_cast<std::uint64_t>(h.vox_offset) + voxels * static_cast<std::uint64_t>(h.bitpix / 8);
  const DataScan data = scan_data(file, h, swapped != 0, needed);
  if (data.bytes < needed)
    fail(name,
         "truncated: the header declares " + std::to_string(needed) + " bytes, the file holds " +
             std::to_string(data.bytes),
         "the file was cut short (an interrupted copy or download?)");
  if (data.non_finite > 0)
    fail(name, std::to_string(data.non_finite) + " voxels are not finite numbers (NaN or infinite)",
         "the volume is corrupt; export it again");
}

}  // namespace vesica::io::detail
