#pragma once
// Label maps of the bladder passed between stages (segment -> surface), read and written
// with ITK, format by extension:
//  .nii / .nii.gz  NIfTI-1
//  .nrrd / .nhdr   NRRD
//  .mha / .mhd     MetaImage
//  .seg.nrrd       3D Slicer segmentation (SlicerSegmentation.h)
// Geometry in millimetres, ITK/DICOM patient space (LPS):
//   x_mm = origin + direction * diag(spacing) * index.
// Kept free of Eigen: ITK ships its own Eigen copy whose headers clash with the system's
// in one translation unit.
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace vesica::io {

struct LabelMap {
  std::array<int, 3> size{};                                   // voxels along i, j, k
  std::array<double, 3> spacing_mm{1, 1, 1};                   // voxel size along i, j, k
  std::array<double, 3> origin_mm{};                           // centre of voxel (0,0,0)
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major; columns: axes
  std::vector<std::uint8_t> voxels;  // 1 inside the bladder, 0 outside; i fastest

  std::size_t voxel_count() const;  // voxels inside
};

// Voxels equal to `label` are inside; label 0 means "any non-zero voxel" (for a Slicer
// segmentation: the segment named "bladder", or its only segment; a .seg.nrrd whose header
// lists no segments is a plain label map). Throws vesica::Error
// naming the file when it cannot be read, is not 3-D, or its spacing, origin or direction
// are not finite and positive (spacing).
LabelMap read_label_map(const std::filesystem::path& path, int label = 0);

// Writes atomically as unsigned 8-bit labels (gzip-compressed for .nii.gz, .nrrd and
// .seg.nrrd). Throws vesica::Error naming the file when ITK cannot write it.
void write_label_map(const LabelMap& map, const std::filesystem::path& path);

bool is_label_map_file(const std::filesystem::path& path);  // by extension

}  // namespace vesica::io
