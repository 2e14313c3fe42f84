#include "vesica/surface/LabelVolume.h"

#include <algorithm>

#include "vesica/core/Error.h"
#include "vesica/io/LabelMap.h"

namespace vesica::surface {

std::size_t LabelVolume::voxel_count() const {
  return static_cast<std::size_t>(std::count(inside.begin(), inside.end(), std::uint8_t{1}));
}

LabelVolume read_label_volume(const std::filesystem::path& path, int label) {
  io::LabelMap raw = io::read_label_map(path, label);
  LabelVolume out;
  out.size = raw.size;
  for (int d = 0; d < 3; ++d) {
    out.spacing_mm(d) = raw.spacing_mm[d];
    out.origin_mm(d) = raw.origin_mm[d];
    for (int e = 0; e < 3; ++e) out.direction(d, e) = raw.direction[3 * d + e];
  }
  out.inside = std::move(raw.voxels);
  if (out.voxel_count() == 0)
    fail(path.string(), "the label map is empty (no voxel with the bladder label)",
         "check the segmentation or pass --label");
  return out;
}

}  // namespace vesica::surface
