#pragma once
// Internal to vesica_io_volumes (VolumeHeaderCheck.h): a guard in front of ITK's NIfTI reader,
// which trusts a header too far: a voxel size of 0 becomes 1 mm, a compressed file cut short is
// zero-filled, and a NaN in the affine aborts the process inside VNL. The header is read with the
// NIfTI library itself and its geometry, data type and data length checked before ITK opens the
// file.
#include <filesystem>

namespace vesica::io::detail {

// Throws vesica::Error(file, ...) naming the first problem found.
void check_nifti_file(const std::filesystem::path& file);

}  // namespace vesica::io::detail
