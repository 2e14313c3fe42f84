#pragma once
// Test label maps made with ITK, and the label boundary measured with ITK, independently
// of the surface library: analytic shapes voxelised through ITK's own index-to-physical
// map, and boundary voxel faces placed through ITK's continuous-index map.
// Plain std types only: ITK's bundled Eigen must not meet the system Eigen in one file.
#include <array>
#include <string>
#include <vector>

namespace vesica::test {

using Vec3 = std::array<double, 3>;

struct GridSpec {
  std::array<int, 3> size{};
  Vec3 spacing{1, 1, 1};
  Vec3 origin{0, 0, 0};
  std::array<double, 9> direction{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major, columns = axes
};

// uint8 label: 1 where the voxel centre's physical point lies inside the axis-aligned
// (in LPS) ellipsoid ((x-c)/a)^2 + ... <= 1. Returns the number of inside voxels.
long write_ellipsoid_label(const std::string& path, const GridSpec& grid, const Vec3& center,
                           const Vec3& semi_axes);

// Boundary between inside (non-zero) and outside voxels of a label map, in LPS mm:
// every voxel face with an inside voxel on one side and an outside voxel (or the image
// border) on the other, as a quad of four corners and its centre.
struct LabelBoundary {
  std::vector<Vec3> face_centres;
  std::vector<std::array<Vec3, 4>> quads;
  long inside_voxels = 0;
  double voxel_volume_mm3 = 0;
};
LabelBoundary label_boundary(const std::string& path);

}  // namespace vesica::test
