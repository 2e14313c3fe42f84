#pragma once
// The wall problem as an FEBio 4 input file (febio_spec 4.0), so that the same problem can
// be run in FEBio Studio: the wall as 3-node shells with vesica's thickness, the material
// and its parameters, the load history (the cavity pressure, or the volumes of a volume-
// stepped or cystometry run) and the held nodes. Where FEBio has no equivalent of a vesica
// feature (the Ogden volumetric term, the tension field, the tissue drag, the
// volume-controlled cavity) the file says so in an XML comment; README "FEBio" tabulates
// the mapping. Units: SI (m, Pa, s) throughout the file, as FEBio takes any consistent set.
#include <filesystem>

#include "vesica/simulate/materials/Material.h"
#include "vesica/simulate/verification/VerificationProtocol.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

struct FebioLoadHistory {
  // true: the cavity pressure rises linearly to max_pressure_pa over `steps` steps;
  // false: the enclosed volume goes from the reference to max_volume_m3 (FEBio has no
  // volume-controlled cavity: written as a comment and as a load curve for reference).
  bool pressure = true;
  double max_pressure_pa = 0.0;
  double max_volume_m3 = 0.0;
  int steps = 20;
};

// The load history of a run: the verification protocols' own, or for a cystometry its
// filling to capacity_ml as volumes.
FebioLoadHistory febio_history(const VerificationSettings& verification, const WallModel& wall,
                               double capacity_ml);

// Writes `path` atomically. Throws vesica::Error for a material FEBio has no law for.
void write_febio(const std::filesystem::path& path, const WallModel& wall,
                 const MaterialSpec& material, const FebioLoadHistory& history);

}  // namespace vesica::simulate
