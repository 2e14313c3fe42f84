#pragma once
// What vesica-simulate's parameter table (SimulateParameters.h) fills: the wall material as
// the command line names it (clinical units), how the imaged wall becomes the reference,
// the protocol and how it is computed. Header-only settings (std and Eigen), so that the
// table's library links core only.
#include <string>
#include <vector>

#include "vesica/simulate/CystometrySettings.h"
#include "vesica/simulate/VerificationSettings.h"
#include "vesica/simulate/WallLoading.h"

namespace vesica::simulate {

struct SimulateSettings {
  // Wall material (docs/physics.md §2), in kPa where the library takes Pa.
  std::string material = "neo-hookean";
  double mu_kpa = 5.0;
  double k_kpa = 0.0;  // 0 = auto: K = 1000 mu, nearly incompressible
  double k1_kpa = 10.0;
  double k2 = 1.0;
  std::vector<double> beta;   // Maxwell branch strengths (-)
  std::vector<double> tau_s;  // their relaxation times (s), as many as beta
  WallOptions wall;           // thickness, reference state, residual volume
  ProtocolSettings protocol;  // the cystometry and the surroundings
  // One posture for both: the wall's fixed patch (WallOptions) and gravity (ProtocolSettings).
  Posture posture = Posture::Supine;
  RunOptions run;  // level, dynamics, level-2 steps, series
  // Issue 25: the volumetric law, the verification protocols and the FEBio export.
  double beta_vol = 9.0;  // Ogden β; 0 = K/2 (ln J)² (docs/physics.md §2.3)
  VerificationSettings verification;
  std::string export_feb;  // empty = none
};

}  // namespace vesica::simulate
