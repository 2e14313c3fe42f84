#include "NiftiCheck.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include <nifti1_io.h>

#include "vesica/core/Error.h"

namespace vesica::segment {
namespace {

constexpr double kMinDeterminant = 1e-12;  // of the sform's 3x3 part, mm^3

bool finite(std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

// The bytes the file holds from its start (decompressed for .nii.gz), up to `wanted`.
std::uint64_t readable_bytes(const std::filesystem::path& file, std::uint64_t wanted) {
  const std::string name = file.string();
  znzFile f = znzopen(name.c_str(), "rb", nifti_is_gzfile(name.c_str()));
  if (znz_isnull(f)) return 0;
  std::vector<char> buffer(1 << 20);
  std::uint64_t total = 0;
  while (total < wanted) {
    const std::size_t n = znzread(buffer.data(), 1, buffer.size(), f);
    if (n == 0) break;
    total += n;
  }
  znzclose(f);
  return total;
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
  if (h.bitpix <= 0 || h.bitpix % 8 != 0) fail(name, "bits per voxel is not a whole byte count");
  check_geometry(h, name);
  if (!finite({h.scl_slope, h.scl_inter})) fail(name, "intensity scaling is not finite");
  if (!finite({h.vox_offset}) || h.vox_offset < 0) fail(name, "data offset is not valid");
  // ITK zero-fills what a short file lacks; the data must be there in full.
  const std::uint64_t needed =
      static_cast<std::uint64_t>(h.vox_offset) + voxels * static_cast<std::uint64_t>(h.bitpix / 8);
  const std::uint64_t have = readable_bytes(file, needed);
  if (have < needed)
    fail(name,
         "truncated: the header declares " + std::to_string(needed) + " bytes, the file holds " +
             std::to_string(have),
         "the file was cut short (an interrupted copy or download?)");
}

}  // namespace vesica::segment
