#pragma once
// The wall's law as FEBio 4 materials (docs/simulate.md, "FEBio"): the <Material> section
// of an export (FebioExport.h), from the model card's material as it ran.
//   neo-Hookean matrix mu, K, beta_vol 0   Mooney-Rivlin c1 = mu/2, c2 = 0, k = K: the same law
//   Maxwell branches beta_a, tau_a         uncoupled viscoelastic g_a = beta_a, t_a = tau_a
//   two fiber families k1, k2              uncoupled solid mixture + two fiber-exp-pow-uncoupled
//                                          (ksi = k1, alpha = k2, beta = 2) on each element's
//                                          own directions (the element maps fiber1, fiber2):
//                                          approximated, see fiber_bulk_modulus()
// The uncoupled laws, because FEBio's shells carry a nearly incompressible wall only in
// their three-field form (FebioMesh.h).
#include <string>

#include "verification/FebioGaps.h"
#include "vesica/simulate/ModelCard.h"

namespace vesica::simulate {

struct FebioMaterialSection {
  std::string xml;          // the <Material> section with its comments
  bool fiber_maps = false;  // the law reads the element maps fiber1 and fiber2
};

// instantaneous: the Maxwell branches as vesica's quasi-static steps have them (dt = 0),
// the passive stress times 1 + Σβ (FebioLoadHistory::instantaneous). Gaps: the Ogden
// volumetric term (beta_vol > 0), the fibers (on the full I4) and the muscle's tone.
FebioMaterialSection febio_material(const MaterialCard& material, bool instantaneous,
                                    FebioGaps& gaps);

}  // namespace vesica::simulate
