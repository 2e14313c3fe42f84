#include "vesica/compare/analysis/RecordingAnalysis.h"

#include <nlohmann/json.hpp>

namespace vesica::compare {

RecordingAnalysis analyse(Recording recording, const ArtefactOptions& options,
                          const RecordingFacts& facts) {
  RecordingAnalysis a;
  a.recording = std::move(recording);
  std::string volume_note;
  if (!a.recording.has_volume() && !a.recording.voided_ml.empty()) {
    const double voided = a.recording.voided_ml.back();
    a.recording.start_volume_ml = facts.capacity_ml > 0 ? facts.capacity_ml : voided;
    if (facts.capacity_ml <= 0)
      volume_note =
          "a voiding table without bladder volume: the volume before voiding is "
          "taken as the voided volume (no residual; give --capacity-ml)";
  }
  a.flags = find_artefacts(a.recording, options);
  a.flagged = flagged_rows(a.recording, a.flags);
  a.ics = compute_ics(a.recording, a.flags);
  if (facts.fill_rate_ml_min > 0) a.ics.fill_rate_ml_min = facts.fill_rate_ml_min;
  if (!volume_note.empty()) a.ics.notes.push_back(volume_note);
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
