#include "vesica/compare/RecordingAnalysis.h"

namespace vesica::compare {

RecordingAnalysis analyse(Recording recording, const ArtefactOptions& options) {
  RecordingAnalysis a;
  a.recording = std::move(recording);
  a.flags = find_artefacts(a.recording, options);
  a.flagged = flagged_rows(a.recording, a.flags);
  a.ics = compute_ics(a.recording, a.flags);
  a.filling = filling_curve(a.recording, a.ics, a.flagged);
  return a;
}

nlohmann::json to_json(const RecordingAnalysis& a) {
  nlohmann::json flags = nlohmann::json::array();
  for (const auto& f : a.flags)
    flags.push_back({{"line", f.line}, {"event", f.event}, {"kind", f.kind}, {"detail", f.detail}});
  return {{"source", a.recording.source},
          {"rows", a.recording.rows()},
          {"parameters", to_json(a.ics)},
          {"artefacts", flags}};
}

}  // namespace vesica::compare
