#pragma once
// Rows of a recording whose pressures cannot be trusted as detrusor pressure:
//  - "abdominal spike": Pves and Pabd both rise at least `spike_cmh2o` above the mean of
//    their neighbouring rows (a cough or a strain reaches both catheters together);
//  - "straining": Pdet below -`negative_pdet_cmh2o` (Pabd above Pves: abdominal straining
//    or a displaced rectal catheter; a true detrusor pressure is never negative);
//  - "pdet mismatch": the recorded Pdet channel differs from Pves - Pabd by more than
//    `mismatch_cmh2o` (1 cmH2O is what rounding each channel to integers can explain).
// Flagged rows are kept in the recording but left out of pressure parameters and fits.
#include <string>
#include <vector>

#include "vesica/compare/recording/Recording.h"

namespace vesica::compare {

struct ArtefactOptions {
  double spike_cmh2o = 5.0;
  double negative_pdet_cmh2o = 1.0;
  double mismatch_cmh2o = 1.0;
};

struct ArtefactFlag {
  std::size_t row = 0;  // index into the recording
  int line = 0;         // 1-based line in the source file
  std::string event;    // the row's event label
  std::string kind;     // "abdominal spike", "straining", "pdet mismatch"
  std::string detail;   // the numbers that triggered it
};

std::vector<ArtefactFlag> find_artefacts(const Recording& recording,
                                         const ArtefactOptions& options = {});

// One flag per row index: true where any artefact was found.
std::vector<bool> flagged_rows(const Recording& recording, const std::vector<ArtefactFlag>& flags);

}  // namespace vesica::compare
