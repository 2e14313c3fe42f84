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
  // A run at one end of the study's `uncertainty:` ranges: the end's name, the run it
  // bounds ("" for the shared run) and the end's own parameters (stage -> parameters; in
  // `overrides` too, after the bounded run's). Empty for an ordinary run.
  std::string bound;
  std::string bound_of;
  std::map<std::string, std::vector<Param>> bound_overrides;
};

// How many runs a study expands to, computed without expanding it; kTooManyRuns when the
// product exceeds it (the count saturates instead of overflowing).
inline constexpr long long kTooManyRuns = 1'000'000'000'000LL;
long long study_run_count(const StudySpec& study);

// No study: an empty list. Matrix runs are named "param-value_param-value"; with variants
// as well, "variant_param-value". With `uncertainty:` ends, each run is followed by one run
// per end, named "<run>_<end>" ("<end>" for the shared run, when the study has no other).
std::vector<StudyRun> expand_study(const StudySpec& study);

// The parameters of a stage after a run's overrides (same key replaced, new key appended).
std::vector<Param> apply_overrides(const std::vector<Param>& base,
                                   const std::vector<Param>& overrides);

}  // namespace vesica::pipelines
