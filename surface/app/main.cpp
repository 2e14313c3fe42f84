// vesica-surface: label map (or surface file) -> closed, remeshed, region-tagged surface;
// or a what-if shape (--shape) at a prescribed volume. Its options are the surface
// parameter table (SurfaceParameters.h).
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/ParameterCli.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/StageRecord.h"
#include "vesica/surface/SurfaceParameters.h"
#include "vesica/surface/SurfaceSettings.h"
#include "vesica/surface/SurfaceStage.h"

namespace {

using vesica::surface::SurfaceSettings;
using vesica::surface::SurfaceStageOptions;

SurfaceStageOptions stage_options(const SurfaceSettings& settings) {
  SurfaceStageOptions options = settings.stage;
  if (!settings.shape.empty()) {
    options.shape = settings.shape_spec;
    options.shape->kind = vesica::surface::shape_kind_from_name(settings.shape);
  } else if (options.input.empty()) {
    vesica::usage_error("give a label map or surface file, or --shape");
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Label map -> closed, remeshed, region-tagged bladder surface (mm, LPS)",
               "vesica-surface"};
  vesica::CommonOptions common;
  SurfaceSettings settings;
  vesica::ParameterTable table = vesica::surface::parameter_table(settings);
  app.add_option("input", settings.stage.input,
                 "label map (.nii.gz/.nrrd/.mha) or surface (.vtp/.stl/.ply/.obj)");
  app.add_option("-o,--output", settings.stage.output, "output surface .vtp/.stl/.ply/.obj")
      ->required();
  vesica::add_parameter_options(app, table);
  vesica::add_common_options(app, common);

  return vesica::run_stage_main(app, argc, argv, common, [&] {
    const SurfaceStageOptions options = stage_options(settings);
    vesica::StageRecord record("vesica-surface", argc, argv);
    record.parameters() = table.values();
    vesica::surface::run_surface_stage(options, record);
    const auto summary =
        record.write(common.report, vesica::default_manifest_path(common, options.output));
    if (common.json) std::cout << summary.dump(2) << std::endl;
    return 0;
  });
}
