#pragma once
// What vesica-surface's parameter table (SurfaceParameters.h) fills: the stage's options,
// and the what-if shape when one is named.
#include <string>

#include "vesica/surface/SurfaceStage.h"

namespace vesica::surface {

struct SurfaceSettings {
  SurfaceStageOptions stage;
  std::string shape;     // "" = build from the input; else sphere, ellipsoid or pouch
  ShapeSpec shape_spec;  // volume, elongation, neck and semi-axes of that shape
};

}  // namespace vesica::surface
