#pragma once
// Internal: the header keys of a one-segment Slicer segmentation (SlicerSegmentation.h)
// for a label map, as (key, value) pairs for ITK's NRRD writer.
#include <string>
#include <utility>
#include <vector>

#include "vesica/io/LabelMap.h"

namespace vesica::io::detail {

std::vector<std::pair<std::string, std::string>> slicer_header_keys(const LabelMap& map);

}  // namespace vesica::io::detail
