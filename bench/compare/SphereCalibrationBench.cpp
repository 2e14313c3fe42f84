// Benchmark: a one-parameter calibration (mu) on a spherical wall of 2,312 triangles
// (close to the thesis's 2,292) against a filling curve simulated with mu = 3 kPa, from a
// start of 6 kPa. Prints one JSON object (seconds, simulations, fitted mu, RMSE).
#include <iostream>

#include <nlohmann/json.hpp>

#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/calibration/Calibration.h"
#include "vesica/simulate/wall/SphereMesh.h"

namespace vc = vesica::compare;
namespace vs = vesica::simulate;

int main() {
  vc::CalibrationProblem pb;
  vc::CystometryModel& m = pb.model;
  m.wall = vs::sphere_wall(0.02285, 3e-3, 17);  // 8 * 17² = 2,312 triangles, 50 ml
  vs::fix_sphere_rigid_modes(m.wall);
  m.protocol.start_ml = 50;
  m.protocol.capacity_ml = 350;
  m.protocol.gravity = false;
  m.protocol.void_after_fill = false;
  m.run.filling_only = true;
  m.material = {"neo-hookean", {{"mu", 3e3}, {"K_per_mu", 1e3}}};  // the default wall
  const auto truth = vs::run_cystometry(m.wall, m.material, m.protocol, m.run);
  pb.targets = vc::filling_targets(vc::analyse(vc::recording_from_history(truth.history)), 50, 350);
  vc::ModelParameter mu = vc::model_parameter("mu");
  mu.fit.initial = 6.0;
  pb.parameters = {mu};
  const auto fit = vc::calibrate(pb).result;
  std::cout << nlohmann::json{{"triangles", m.wall.triangle_count()},
                              {"truth_completed", truth.completed},
                              {"seconds", fit.seconds},
                              {"target_seconds", 60},
                              {"simulations", fit.simulations},
                              {"fitted_mu_kpa", fit.parameters.at(0).value},
                              {"ci95_mu_kpa",
                               {fit.parameters.at(0).ci_low, fit.parameters.at(0).ci_high}},
                              {"true_mu_kpa", 3.0},
                              {"rmse_cmh2o", fit.rmse_cmh2o},
                              {"status", fit.status}}
                   .dump()
            << std::endl;
  return 0;
}
