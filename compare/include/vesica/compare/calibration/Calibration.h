#pragma once
// Calibration of vesica's cystometry model to a recording (docs/physics.md §9): the
// parameters the model can fit and how each enters its settings, the model and its fast
// surrogate as ModelSimulators (vesica::simulate::run_cystometry in this process, no
// files), and the two-stage fit (TwoStageFit.h) over them.
//
// The surrogate is simulate's level 0 (the wall's sphere-equivalent: the same material,
// activation and urethra laws, milliseconds a cystometry); the wall is run a few times by
// the output space mapping and once more for the whole data.
#include <functional>
#include <string>
#include <vector>

#include "vesica/compare/calibration/CalibrationResult.h"
#include "vesica/compare/calibration/CalibrationTargets.h"
#include "vesica/compare/calibration/FitParameter.h"
#include "vesica/compare/calibration/ModelRun.h"
#include "vesica/compare/calibration/TwoStageFit.h"
#include "vesica/simulate/protocol/Cystometry.h"

namespace vesica::compare {

// A parameter the calibration can fit: its search range (FitParameter) and how its value
// (in FitParameter::unit) enters the model.
struct ModelParameter {
  FitParameter fit;
  std::function<void(double value, simulate::MaterialSpec&, simulate::ProtocolSettings&)> apply;
};

// Every parameter by name; throws a usage error naming the choices for an unknown one.
ModelParameter model_parameter(const std::string& name);
std::vector<std::string> model_parameter_names();

// One simulated cystometry setting: wall, material, protocol, numerics.
struct CystometryModel {
  simulate::WallModel wall;
  simulate::MaterialSpec material;
  simulate::ProtocolSettings protocol;
  simulate::RunOptions run;
};

// Simulates a parameter vector on `base`: applies the values, fills to capacity_ml and, with
// `voiding`, voids; a run that fails is retried once with halved steps. `differentiated`:
// the fit takes finite differences of its runs (every Newton iteration a fresh tangent).
ModelSimulator cystometry_simulator(const CystometryModel& base,
                                    const std::vector<ModelParameter>& parameters,
                                    double capacity_ml, bool voiding, bool differentiated);

// The fast surrogate of a model: the same wall, material and protocol at level 0.
CystometryModel surrogate_of(const CystometryModel& model);

struct CalibrationProblem {
  CystometryModel model;  // start values; fitted entries overwritten per run
  std::vector<ModelParameter> parameters;
  CalibrationTargets targets;
  double data_end_ml = 0;  // the recording's end of filling (0: targets.capacity_ml)
  bool use_surrogate = true;
  FitBudget budget;
};

// The result and the fitted model's run over the whole data.
FitOutcome calibrate(const CalibrationProblem& problem);

// A simulation history as a Recording (so simulated curves use the history.csv definitions).
Recording recording_from_history(const std::vector<simulate::HistoryRow>& history);

}  // namespace vesica::compare
