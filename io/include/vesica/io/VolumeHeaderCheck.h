#pragma once
// One check of a volume file's header, made before any reader allocates what the header
// claims, shared by every stage that reads volumes (segment's CT/MR volumes, surface's
// label maps): a header of a few bytes may claim 1000^3 voxels, and a reader would spend
// minutes and gigabytes before it failed. The check costs no more than the header:
//  - the file is a regular file of bounded size (InputFile.h), as is every data file a
//    detached header (.nhdr, .mhd) names;
//  - the voxel count is within the memory budget (kMaxVolumeVoxels);
//  - uncompressed data fits the file; compressed data fits zlib's largest ratio;
//  - NIfTI: its header through the NIfTI library (geometry, data type, data length,
//    non-finite voxels), as ITK's NIfTI reader trusts it too far.
#include <cstdint>
#include <filesystem>
#include <string>

namespace vesica::io {

// 512 x 512 x 1024: a CT of 2000 thin slices at full resolution is cropped first. Every
// copy a stage makes (float: 1 GiB) stays within a workstation's memory.
inline constexpr std::uint64_t kMaxVolumeVoxels = std::uint64_t{1} << 28;

// Throws vesica::Error naming `file` when `voxels` exceeds kMaxVolumeVoxels.
void require_voxel_budget(const std::string& file, std::uint64_t voxels);

// The checks above for a .nii, .nii.gz, .nrrd, .nhdr, .mha or .mhd file (the format from its
// name; other names are left to the reader). Throws vesica::Error naming the file.
void check_volume_file(const std::filesystem::path& path);

}  // namespace vesica::io
