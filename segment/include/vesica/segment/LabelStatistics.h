#pragma once
// Numbers that describe a label map in patient millimetres (LPS): what the segment
// summary reports and what the tests compare against reference segmentations.
#include <array>
#include <cstdint>

#include "vesica/segment/ImageTypes.h"

namespace vesica::segment {

struct LabelStatistics {
  std::uint64_t voxel_count = 0;
  double volume_ml = 0;
  std::array<double, 3> centroid_mm{};  // mean voxel-centre position
  std::array<double, 3> bbox_min_mm{};  // over voxel centres
  std::array<double, 3> bbox_max_mm{};
};

// Statistics of all non-zero voxels.
LabelStatistics label_statistics(const LabelImage& label);

// Dice overlap 2|A∩B|/(|A|+|B|) of two labels on the same grid (non-zero = inside).
double dice(const LabelImage& a, const LabelImage& b);

// `label` resampled onto the grid of `like` (linear interpolation of the 0/1 values,
// then the 0.5 level); for comparing labels from grids of different orientation.
LabelImage::Pointer resample_label_like(const LabelImage& label, const LabelImage& like);

}  // namespace vesica::segment
