#include "vesica/surface/LabelVolume.h"

#include <algorithm>

#include "ItkLabelReader.h"
#include "vesica/core/Error.h"

namespace vesica::surface {

std::size_t LabelVolume::voxel_count() const {
  return static_cast<std::size_t>(std::count(inside.begin(), inside.end(), std::uint8_t{1}));
}

LabelVolume read_label_volume(const std::filesystem::path& path, int label) {
  if (!std::filesystem::exists(path)) fail(path.string(), "label map not found");
  detail::ItkLabel raw = detail::read_itk_label(path.string(), label);
  LabelVolume out;
  out.size = raw.size;
  for (int d = 0; d < 3; ++d) {
    out.spacing_mm(d) = raw.spacing[d];
    out.origin_mm(d) = raw.origin[d];
    for (int e = 0; e < 3; ++e) out.direction(d, e) = raw.direction[3 * d + e];
  }
  out.inside = std::move(raw.inside);
  if (out.voxel_count() == 0)
    fail(path.string(), "the label map is empty (no voxel with the bladder label)",
         "check the segmentation or pass --label");
  return out;
}

}  // namespace vesica::surface
