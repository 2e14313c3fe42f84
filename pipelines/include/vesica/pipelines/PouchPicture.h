#pragma once
// A small picture of one variant's wall at capacity for the study table: the outline seen
// from the front (vesica-compare's anterior projection, farthest triangles first), every
// triangle filled by its maximum principal stress σ1 on the study's common viridis scale,
// the outlet ringed and the largest σ1 crossed. All pictures share one scale in mm, so
// that sizes compare as well as shapes.
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace vesica::pipelines {

struct PictureScale {
  double stress_max_kpa = 1.0;  // the top of the colour scale (0 at the bottom)
  double px_per_mm = 1.0;
  int size_px = 96;
};

// `stress`: the JSON of CapacityStress.h; "" when it has no projection.
std::string pouch_picture(const nlohmann::json& stress, const PictureScale& scale);
// The largest outline extent (mm) of a set of pictures' projections, to fit them all.
double projection_extent_mm(const nlohmann::json& stress);
// The colour scale as a small horizontal bar labelled 0 and the maximum.
std::string stress_scale_bar(const PictureScale& scale);

}  // namespace vesica::pipelines
