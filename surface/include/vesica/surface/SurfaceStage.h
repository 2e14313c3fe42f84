#pragma once
// The surface stage as a function: label map (or surface file, or a what-if shape) ->
// checked, region-tagged surface file plus the summary numbers. app/main.cpp only parses.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vesica/core/StageRecord.h"
#include "vesica/surface/Isosurface.h"
#include "vesica/surface/LabelSanity.h"
#include "vesica/surface/PolygonMeshProcessing.h"
#include "vesica/surface/Shapes.h"
#include "vesica/surface/SurfaceIO.h"
#include "vesica/surface/SurfaceRegions.h"

namespace vesica::surface {

struct SurfaceStageOptions {
  std::string input;   // label map or surface file; empty with a shape
  std::string output;  // .vtp/.stl/.ply/.obj
  int label = 0;       // label value inside the bladder; 0 = any non-zero voxel
  std::optional<ShapeSpec> shape;
  std::optional<Eigen::Vector3d> morph;  // principal-axis stretches
  SmoothingOptions smoothing;
  double edge_mm = 0.0;      // remeshing target; 0 = from target_triangles or 4 mm
  int target_triangles = 0;  // alternative to edge_mm
  int remesh_iterations = 5;
  bool volume_rescale = true;       // label input: rescale to the label's voxel volume
  LabelSanityOptions label_sanity;  // label input: one piece, cavities filled, minimum size
  RepairOptions repair;
  RegionOptions regions;
  WriteOptions write;
};

// Builds, checks (throws vesica::Error naming the output when a check fails, before
// writing), tags and writes the surface; fills record's summary, inputs, outputs and
// timings, and adds the edge length used to its parameters (the options' values are the
// parameter table's, SurfaceParameters.h).
TriangleSurface run_surface_stage(const SurfaceStageOptions& options, StageRecord& record);

// Summary numbers of a finished surface: volume, area, counts, quality, checks.
nlohmann::json surface_summary(const TriangleSurface& surface, const SurfaceChecks& checks);

}  // namespace vesica::surface
