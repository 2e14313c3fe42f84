#pragma once
// vesica-surface's parameter table: every option of the command line and every `params`
// key of a surface stage in a pipeline file, with unit, range, help and the default of the
// library struct it is bound to. Depends only on core (and header-only settings), so the
// runner links it to check pipeline files before any stage runs.
#include <string>

#include "vesica/core/ParameterTable.h"
#include "vesica/surface/SurfaceStage.h"

namespace vesica::surface {

// What the table fills: the stage's options, and the what-if shape when one is named.
struct SurfaceSettings {
  SurfaceStageOptions stage;
  std::string shape;     // "" = build from the input; else sphere, ellipsoid or pouch
  ShapeSpec shape_spec;  // volume, elongation, neck and semi-axes of that shape
};

ParameterTable parameter_table(SurfaceSettings& settings);

}  // namespace vesica::surface
