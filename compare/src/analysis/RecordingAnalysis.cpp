#include "vesica/compare/analysis/RecordingAnalysis.h"

#include <nlohmann/json.hpp>

namespace vesica::compare {

RecordingAnalysis analyse(Recording recording, const ArtefactOptions& options,
                          const RecordingFacts& facts) {
  RecordingAnalysis a;
  a.recording = std::move(recording);
  std::string volume_note, flow_note;
  // Flow without a voided-volume column: the voided volume is the flow's integral, so that
  // the bladder volume falls while voiding and PVR is not the whole capacity
  // (docs/compare.md, plausibility rule flow-without-voided).
  if (a.recording.has_flow() && a.recording.voided_ml.empty() && a.recording.has_time()) {
    a.recording.voided_ml = a.recording.voided_or_integrated_ml();
    flow_note = "no voided-volume column: the voided volume is the integral of the flow";
  }
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
  if (!flow_note.empty()) a.ics.notes.push_back(flow_note);
  a.filling = filling_curve(a.recording, a.ics, a.flagged);
  return a;
}

RecordingAnalysis analyse_checked(Recording recording, const ArtefactOptions& options,
                                  const RecordingFacts& facts) {
  std::vector<PlausibilityWarning> warnings = check_plausibility(recording);
  RecordingAnalysis a = analyse(std::move(recording), options, facts);
  if (a.ics.compliance_ml_per_cmh2o)
    for (auto& w : check_compliance(*a.ics.compliance_ml_per_cmh2o)) warnings.push_back(w);
  a.warnings = std::move(warnings);
  return a;
}

nlohmann::json to_json(const RecordingAnalysis& a) {
  nlohmann::json flags = nlohmann::json::array();
  for (const auto& f : a.flags)
    flags.push_back({{"line", f.line}, {"event", f.event}, {"kind", f.kind}, {"detail", f.detail}});
  nlohmann::json warnings = nlohmann::json::array();
  for (const auto& w : a.warnings) warnings.push_back({{"rule", w.rule}, {"message", w.message}});
  return {{"source", a.recording.source},
          {"rows", a.recording.rows()},
          {"parameters", to_json(a.ics)},
          {"artefacts", flags},
          {"plausibility_warnings", warnings}};
}

}  // namespace vesica::compare
