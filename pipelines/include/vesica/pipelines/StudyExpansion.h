#pragma once
// A study turns one pipeline into several runs: the cartesian product of `matrix` axes,
// times the named `variants`. Each run is a name and the parameters it sets per stage.
#include <map>
#include <string>
#include <vector>

#include "vesica/pipelines/PipelineFile.h"

namespace vesica::pipelines {

struct StudyRun {
  std::string name;                                     // folder name under variants/
  std::map<std::string, std::vector<Param>> overrides;  // stage -> parameters it sets
};

// How many runs a study expands to, computed without expanding it; kTooManyRuns when the
// product exceeds it (the count saturates instead of overflowing).
inline constexpr long long kTooManyRuns = 1'000'000'000'000LL;
long long study_run_count(const StudySpec& study);

// No study: an empty list. Matrix runs are named "param-value_param-value"; with variants
// as well, "variant_param-value".
std::vector<StudyRun> expand_study(const StudySpec& study);

// The parameters of a stage after a run's overrides (same key replaced, new key appended).
std::vector<Param> apply_overrides(const std::vector<Param>& base,
                                   const std::vector<Param>& overrides);

}  // namespace vesica::pipelines
