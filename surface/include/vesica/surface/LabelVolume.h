#pragma once
// A binary label map on its image grid with the geometry ITK gives it, so that the
// isosurface can be placed exactly where ITK's TransformIndexToPhysicalPoint puts voxels:
//   x_mm = origin + direction * diag(spacing) * index   (LPS).
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include <Eigen/Core>

namespace vesica::surface {

struct LabelVolume {
  std::array<int, 3> size{0, 0, 0};     // voxels along i, j, k
  Eigen::Vector3d spacing_mm{1, 1, 1};  // voxel size along i, j, k
  Eigen::Vector3d origin_mm{0, 0, 0};   // physical position of voxel (0,0,0)'s centre
  Eigen::Matrix3d direction = Eigen::Matrix3d::Identity();  // columns: i, j, k axes in LPS
  std::vector<std::uint8_t> inside;  // 1 inside the label, 0 outside; i fastest

  std::size_t voxel_count() const;  // voxels inside
  double voxel_volume_mm3() const { return spacing_mm.prod(); }
  // Physical point (mm, LPS) of a continuous index.
  Eigen::Vector3d physical_point(const Eigen::Vector3d& index) const {
    return origin_mm + direction * spacing_mm.asDiagonal() * index;
  }
};

// Reads a label map through vesica_io (vesica/io/LabelMap.h: .nii/.nii.gz/.nrrd/.mha, and
// 3D Slicer's .seg.nrrd). Voxels equal to `label` are inside; label 0 means "any non-zero
// voxel" (a Slicer segmentation: its "bladder" segment). Throws vesica::Error on an
// unreadable file or an empty label.
LabelVolume read_label_volume(const std::filesystem::path& path, int label = 0);

}  // namespace vesica::surface
