#pragma once
// The wall problem as an FEBio 4 input (febio_spec 4.0), written from what vesica ran: the
// model card's material with every value as it ran, the stress-free wall as 3-node shells
// with vesica's thickness and fiber directions, the held nodes, and the transmural
// pressure along time as vesica computed it (a verification's pressure steps, or a
// cystometry's settling and filling). FEBio, loaded with the same pressures, then gives the
// volumes to compare with vesica's: the same P–V curve where both codes solve the same
// problem. The law-by-law mapping, and what FEBio cannot express (an error naming the
// parameter, or with `approximate` FEBio's nearest law and a warning saying which):
// docs/simulate.md, "FEBio". Units in the file: SI (m, Pa, s).
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/io/HistoryCsv.h"
#include "vesica/simulate/ModelCard.h"
#include "vesica/simulate/verification/VerificationProtocol.h"
#include "vesica/simulate/wall/WallModel.h"

namespace vesica::simulate {

// The transmural pressure on the wall (Pa) along time (s) from the stress-free wall at
// (0, 0): FEBio's pressure load curve, and the times at which FEBio's automatic time
// stepping stops and writes the wall (its must points).
struct FebioLoadHistory {
  std::vector<double> time_s;
  std::vector<double> pressure_pa;
  // vesica's quasi-static verification steps respond instantaneously (dt = 0, docs/physics.md
  // §2.5): the Maxwell branches then multiply the passive stress by 1 + Σβ, which the file
  // writes as the elastic law with its moduli scaled (exact). false: the branches relax
  // along the curve's time, as in a cystometry.
  bool instantaneous = false;
  std::string description;  // what the curve is, for the file's comment
};

// A verification run's converged pressures (its rows) at unit time intervals. Volume steps
// past a limit point cannot be followed under pressure: the curve stops at the highest
// pressure (said in the description).
FebioLoadHistory febio_verification_history(const VerificationResult& result);

// A cystometry's settling and filling (its hold included; the rows before voiding): the
// settling from the stress-free reference to the first row's pressure as a ramp long
// against every relaxation time of the material (vesica settles with relaxed branches),
// then Pdet = Pves − Pabd at the recorded times. Throws vesica::Error when the history has
// no filling.
FebioLoadHistory febio_filling_history(const std::vector<io::HistoryRow>& history,
                                       const ProtocolSettings& protocol,
                                       const MaterialCard& material);

struct FebioExportOptions {
  // Write FEBio's nearest law where it has no equal, with a warning saying which, instead
  // of refusing.
  bool approximate = false;
  // The cystometry's settings and numerics (its surroundings, reference and level); null
  // for a verification, which has none of them.
  const ModelCard* cystometry = nullptr;
};

// What the file cannot hold exactly, one line each ("beta_vol = 9: ..."), in the order the
// file meets them. Throws vesica::Error (usage) for the first one unless
// options.approximate, and for what has no nearest law at all, so that a run can refuse an
// export before it starts.
std::vector<std::string> febio_approximations(const MaterialCard& material,
                                              const FebioExportOptions& options);

// Writes `path` atomically (the wall as WallModel holds it: its stress-free reference) and
// returns febio_approximations(); throws as it does.
std::vector<std::string> write_febio(const std::filesystem::path& path, const WallModel& wall,
                                     const MaterialCard& material, const FebioLoadHistory& history,
                                     const FebioExportOptions& options);

}  // namespace vesica::simulate
