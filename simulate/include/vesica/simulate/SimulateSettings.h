#pragma once
// What vesica-simulate's parameter table (SimulateParameters.h) fills: the wall material as
// the command line names it (clinical units), how the imaged wall becomes the reference,
// the protocol and how it is computed. Header-only settings (std and Eigen), so that the
// table's library links core only.
#include <string>
#include <vector>

#include "vesica/simulate/protocol/CystometrySettings.h"
#include "vesica/simulate/verification/VerificationSettings.h"
#include "vesica/simulate/wall/WallLoading.h"

namespace vesica::simulate {

// A material parameter not given: the material's own default (MaterialRegistry.h).
constexpr double kMaterialDefault = -1.0;

struct SimulateSettings {
  // Wall material (docs/physics.md §2), in kPa where the library takes Pa; every
  // parameter defaults to the named material's own value (kMaterialDefault).
  std::string material = "bladder";
  double mu_kpa = kMaterialDefault;
  double k_kpa = kMaterialDefault;  // the material's: K = 1000 mu, nearly incompressible
  double k1_kpa = kMaterialDefault;
  double k2 = kMaterialDefault;
  std::vector<double> beta;   // Maxwell branch strengths (-); none given: the material's
  std::vector<double> tau_s;  // their relaxation times (s), as many as beta
  // The detrusor muscle (docs/physics.md §2.6): nominal active stress at rest and added at
  // full activation (kPa), length–tension optimum and width, Hill's a/T0 and v_max (1/s).
  double tone_kpa = kMaterialDefault;
  double detrusor_kpa = kMaterialDefault;
  double optimal_stretch = kMaterialDefault;
  double stretch_width = kMaterialDefault;
  double hill_a = kMaterialDefault;
  double hill_vmax_per_s = kMaterialDefault;
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
