// vesica-compare: ICS urodynamic parameters of a measured and/or a simulated recording,
// model-against-measurement metrics, optional calibration, and a self-contained report.
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include <CLI/CLI.hpp>

#include "vesica/compare/CompareRun.h"
#include "vesica/compare/WallStress.h"
#include "vesica/compare/WallStressPicture.h"
#include "vesica/core/Error.h"
#include "vesica/core/StageMain.h"

int main(int argc, char** argv) {
  CLI::App app{"Urodynamic parameters, model against measurement, calibration and report",
               "vesica-compare"};
  vesica::CommonOptions common;
  vesica::add_common_options(app, common);
  vesica::compare::CompareOptions o;
  app.add_option("--measured", o.measured, "Measured cystometry / pressure-flow CSV");
  app.add_option("--simulated", o.simulated, "Simulation history.csv");
  app.add_option("-o,--output", o.output, "Report folder (index.html, metrics.json)");
  app.add_option("--columns", o.columns,
                 "Column names of the measured CSV: KEY=NAME,... (keys: time, event, pves, "
                 "pabd, pdet, flow, voided, infused, volume)");
  app.add_option("--pressure-unit", o.pressure_unit,
                 "Unit of pressure columns without one: cmh2o, kpa, pa, mmhg")
      ->capture_default_str();
  app.add_option("--mesh", o.mesh,
                 "Simulation mesh .vtu: the wall-stress picture (a .vtu of the series at "
                 "capacity) and, with --calibrate, the geometry to simulate");
  app.add_option("--sex", o.sex,
                 "Patient's sex, female or male (default: from the measured recording's header); "
                 "selects the pressure-flow criteria")
      ->check(CLI::IsMember({"female", "male"}));
  app.add_flag("--no-pdf", o.no_pdf, "Do not print report.pdf with headless chromium");
  app.add_option("--calibrate", o.calibrate,
                 "Fit these parameters to the measured Pdet(V): mu[,beta,tau,k1,k2,r1,r2,p_open]");
  app.add_option("--fit-volume-ml", o.fit_volume_ml,
                 "Volumes (ml) compared and fitted: LO,HI (default: the overlap)")
      ->delimiter(',')
      ->expected(2);
  app.add_option("--spike-cmh2o", o.artefacts.spike_cmh2o,
                 "Rise of Pves and Pabd together that flags a cough/strain row")
      ->capture_default_str();
  app.add_option("--mu-kpa", o.simulation.mu_kpa, "Shear modulus to start the calibration from")
      ->capture_default_str();
  app.add_option("--k-kpa", o.simulation.k_kpa,
                 "Bulk modulus of the wall in the calibration (default: 1000 x mu)")
      ->capture_default_str();
  app.add_option("--thickness-mm", o.simulation.thickness_mm, "Wall thickness in the calibration")
      ->capture_default_str();
  app.add_option("--start-ml", o.simulation.start_ml, "Volume the calibration run starts from")
      ->capture_default_str();
  app.add_option("--max-simulations", o.max_simulations, "Calibration budget (level-1 runs)")
      ->capture_default_str();
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
