#pragma once
// The design question of a study answered per variant against the `limits:` of the study
// file: "pass" when every limit holds, "fail" when one does not, "" when a read-out a limit
// needs is missing (not reached, a failed run) and none fails.
#include <string>
#include <utility>
#include <vector>

#include "vesica/pipelines/PipelineFile.h"
#include "vesica/pipelines/StudyMetrics.h"

namespace vesica::pipelines {

using StudyValues = std::vector<std::pair<std::string, StudyValue>>;  // metric -> value

std::string answer(const std::vector<StudyLimit>& limits, const StudyValues& values);

// "Pdet at 500 ml <= 40 cmH2O" (plain text; the page escapes it).
std::string limit_text(const StudyLimit& limit);

}  // namespace vesica::pipelines
