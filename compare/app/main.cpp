// vesica-compare: ICS urodynamic parameters of a measured and/or a simulated recording,
// model-against-measurement metrics, optional calibration, and a self-contained report.
// Its options are the compare parameter table (CompareParameters.h).
#include <filesystem>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include "vesica/compare/CompareParameters.h"
#include "vesica/compare/CompareRun.h"
#include "vesica/compare/analysis/WallStress.h"
#include "vesica/compare/report/WallStressPicture.h"
#include "vesica/core/Error.h"
#include "vesica/core/ParameterCli.h"
#include "vesica/core/StageMain.h"

int main(int argc, char** argv) {
  CLI::App app{"Urodynamic parameters, model against measurement, calibration and report",
               "vesica-compare"};
  vesica::CommonOptions common;
  vesica::add_common_options(app, common);
  vesica::compare::CompareOptions o;
  vesica::ParameterTable table = vesica::compare::parameter_table(o);
  app.add_option("-o,--output", o.output, "Report folder (index.html, metrics.json)");
  vesica::add_parameter_options(app, table);
  // The child process that draws the wall-stress picture (needs an X display).
  std::string render_vtu, render_png, capacity_of;
  app.add_option("--render-wall-stress", render_vtu)->group("");
  app.add_option("--render-png", render_png)->group("");
  // The runner's study page asks for the wall stress at capacity of each simulation.
  app.add_option("--wall-stress-at-capacity", capacity_of)->group("");

  return vesica::run_stage_main(app, argc, argv, common, [&]() {
    if (!render_vtu.empty()) {
      vesica::compare::render_wall_stress_png(render_vtu, render_png);
      return 0;
    }
    if (!capacity_of.empty()) {
      std::cout << vesica::compare::wall_stress_at_capacity(capacity_of).dump() << std::endl;
      return 0;
    }
    return vesica::compare::run_compare(o, common, argc, argv);
  });
}
