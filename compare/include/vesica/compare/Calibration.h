#pragma once
// Calibration of the level-1 bladder model to a measured filling curve (and flow): the
// named parameters are fitted by Levenberg-Marquardt (Eigen, unsupported module) with a
// forward-difference Jacobian; every residual evaluation is one simulated cystometry
// through vesica::simulate::run_cystometry in this process (no files).
//
// Residuals: simulated - measured Pdet (cmH2O) on the 5 ml grid of ModelComparison over
// [volume_lo_ml, volume_hi_ml]; with outlet parameters (r1, r2, p_open) also simulated -
// measured flow (ml/s) on a 1 s grid from the onset of flow.
// Parameters are searched as u = ln p and clamped to their bounds when evaluated; the 95 %
// interval is p ± 1.96 p sqrt(diag(σ² (JᵀJ)⁻¹)) with J = ∂r/∂u at the solution and
// σ² = Σr²/(n - m) (delta method).
#include <string>
#include <vector>

#include "vesica/compare/CalibrationResult.h"
#include "vesica/compare/IcsParameters.h"
#include "vesica/simulate/Cystometry.h"

namespace vesica::compare {

// One parameter the calibration can fit, in the unit it is reported in.
struct ParameterSpec {
  std::string name, unit;
  double initial, lower, upper;
  bool outlet;  // acts on voiding only (needs the flow residuals)
};

// mu (kPa), k (kPa, bulk), beta (-), tau (s), k1 (Pa), k2 (-), r1 (cmH2O s/ml),
// r2 (cmH2O s²/ml²), p_open (cmH2O). Throws a usage error for an unknown name.
ParameterSpec parameter_spec(const std::string& name);

struct CalibrationProblem {
  simulate::WallModel wall;
  simulate::MaterialSpec material;      // start values (SI), fitted keys overwritten
  simulate::ProtocolSettings protocol;  // start values, fitted keys overwritten
  simulate::RunOptions run;
  std::vector<ParameterSpec> parameters;
  Curve measured_filling;  // (volume ml, Pdet cmH2O)
  Curve measured_flow;     // (s since onset of flow, ml/s); used with outlet parameters
  double volume_lo_ml = 0, volume_hi_ml = 0;
  double volume_step_ml = 5.0;
  int max_simulations = 40;
};

CalibrationResult calibrate(const CalibrationProblem& problem);

// A simulation history as a Recording (so simulated curves use the history.csv definitions).
Recording recording_from_history(const std::vector<simulate::HistoryRow>& history);

}  // namespace vesica::compare
