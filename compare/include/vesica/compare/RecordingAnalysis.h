#pragma once
// One recording with everything computed from it: artefact flags, ICS parameters and the
// (unflagged) filling curve Pdet(V).
#include <vector>

#include <nlohmann/json.hpp>

#include "vesica/compare/Artefacts.h"
#include "vesica/compare/IcsParameters.h"
#include "vesica/compare/Recording.h"

namespace vesica::compare {

struct RecordingAnalysis {
  Recording recording;
  std::vector<ArtefactFlag> flags;
  std::vector<bool> flagged;
  IcsParameters ics;
  Curve filling;  // (volume ml, Pdet cmH2O), unflagged filling rows
};

RecordingAnalysis analyse(Recording recording, const ArtefactOptions& options = {});

// {"source", "rows", "parameters", "artefacts": [{line, event, kind, detail}]}
nlohmann::json to_json(const RecordingAnalysis& a);

}  // namespace vesica::compare
