#pragma once
// One recording with everything computed from it: artefact flags, ICS parameters and the
// (unflagged) filling curve Pdet(V).
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "vesica/compare/analysis/IcsParameters.h"
#include "vesica/compare/recording/Artefacts.h"
#include "vesica/compare/recording/Plausibility.h"
#include "vesica/compare/recording/Recording.h"

namespace vesica::compare {

struct RecordingAnalysis {
  Recording recording;
  std::vector<ArtefactFlag> flags;
  std::vector<bool> flagged;
  IcsParameters ics;
  Curve filling;  // (volume ml, Pdet cmH2O), unflagged filling rows
  // What the plausibility rules found short of a refusal (measured recordings only).
  std::vector<PlausibilityWarning> warnings;
};

// What the caller knows that a table may not say (0: not given).
struct RecordingFacts {
  double fill_rate_ml_min = 0;  // replaces the rate inferred from time
  // Bladder volume before voiding, for a voiding table with neither infused nor bladder
  // volume; not given: its voided volume (no residual), said in the notes.
  double capacity_ml = 0;
};

RecordingAnalysis analyse(Recording recording, const ArtefactOptions& options = {},
                          const RecordingFacts& facts = {});

// The recording checked by the plausibility rules (Plausibility.h: a refusal throws), then
// analysed; the rules' warnings, the compliance rule's included, in `warnings`.
RecordingAnalysis analyse_checked(Recording recording, const ArtefactOptions& options = {},
                                  const RecordingFacts& facts = {});

// {"source", "rows", "parameters", "artefacts": [{line, event, kind, detail}],
//  "plausibility_warnings": [{rule, message}]}
nlohmann::json to_json(const RecordingAnalysis& a);

}  // namespace vesica::compare
