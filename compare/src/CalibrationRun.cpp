// --calibrate from the command line: the wall from --mesh, the protocol from the measured
// recording's filling, the fit volumes from --fit-volume-ml (default: the measured filling
// from --start-ml to capacity).
#include <algorithm>
#include <sstream>

#include "vesica/compare/Calibration.h"
#include "vesica/compare/CalibrationRun.h"
#include "vesica/compare/ModelComparison.h"
#include "vesica/core/Error.h"

namespace vesica::compare {
namespace {

std::vector<ParameterSpec> parse_parameters(const std::string& list, const CalibrationModel& m) {
  std::vector<ParameterSpec> specs;
  std::stringstream ss(list);
  for (std::string name; std::getline(ss, name, ',');) {
    if (name.empty()) continue;
    ParameterSpec s = parameter_spec(name);
    if (s.name == "mu") s.initial = m.mu_kpa;
    if (s.name == "k") s.initial = m.k_kpa;
    specs.push_back(s);
  }
  if (specs.empty()) usage_error("--calibrate: no parameter named");
  return specs;
}

std::string material_for(const std::vector<ParameterSpec>& specs) {
  auto fits = [&](const char* n) {
    return std::any_of(specs.begin(), specs.end(), [&](const auto& s) { return s.name == n; });
  };
  if (fits("k1") || fits("k2")) return "fibers";
  if (fits("beta") || fits("tau")) return "maxwell";
  return "neo-hookean";
}

}  // namespace

CalibrationResult calibrate_from_options(const CompareOptions& o,
                                         const RecordingAnalysis& recording,
                                         const ComparisonOptions& comparison) {
  const Curve& measured = recording.filling;
  CalibrationProblem pb;
  pb.parameters = parse_parameters(o.calibrate, o.simulation);
  if (measured.x.size() < 2)
    usage_error("--calibrate: the measured recording has no filling curve");
  const double measured_lo = *std::min_element(measured.x.begin(), measured.x.end());
  const double measured_hi = *std::max_element(measured.x.begin(), measured.x.end());
  pb.volume_lo_ml = std::max(measured_lo, o.simulation.start_ml);
  pb.volume_hi_ml = measured_hi;
  if (comparison.volume_range_ml) {
    pb.volume_lo_ml = std::max(pb.volume_lo_ml, comparison.volume_range_ml->first);
    pb.volume_hi_ml = std::min(pb.volume_hi_ml, comparison.volume_range_ml->second);
  }
  pb.measured_filling = measured;
  pb.max_simulations = o.max_simulations;

  simulate::WallOptions wall_options;
  wall_options.thickness_mm = o.simulation.thickness_mm;
  wall_options.residual_ml = o.simulation.start_ml;
  pb.wall = simulate::load_wall(o.mesh, wall_options);
  pb.material.name = material_for(pb.parameters);
  pb.material.params = {{"mu", o.simulation.mu_kpa * 1e3}};
  if (o.simulation.k_kpa > 0.0)
    pb.material.params["K"] = o.simulation.k_kpa * 1e3;
  else
    pb.material.params["K_per_mu"] = 1e3;  // nearly incompressible, as vesica-simulate
  pb.protocol.start_ml = o.simulation.start_ml;
  // Without gravity: a stress-free membrane at the start volume carries its own weight
  // with no stiffness (no equilibrium), and the measured Pdet is referred to the
  // catheter, not to a hydrostatic column.
  pb.protocol.gravity = false;
  pb.protocol.capacity_ml = std::max(pb.volume_hi_ml, o.simulation.start_ml + 1.0);
  // outlet parameters act on voiding: simulate it and fit the measured flow as well
  const bool outlet = std::any_of(pb.parameters.begin(), pb.parameters.end(),
                                  [](const ParameterSpec& s) { return s.outlet; });
  pb.protocol.void_after_fill = outlet;
  pb.run.filling_only = !outlet;
  if (outlet) {
    pb.measured_flow = voiding_curves(recording.recording, recording.ics).flow_ml_s;
    if (pb.measured_flow.x.size() < 2)
      usage_error("--calibrate: outlet parameters need a measured flow channel");
  }
  return calibrate(pb);
}

}  // namespace vesica::compare
