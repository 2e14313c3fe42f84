#include "vesica/pipelines/StudyExpansion.h"

#include <algorithm>

namespace vesica::pipelines {
namespace {

// Folder-safe text of a value: "0.5" stays, "a,b" becomes "a+b", "/" is dropped.
std::string folder_safe(const Param& p) {
  if (p.kind == Param::Kind::Flag) return "on";
  if (p.kind == Param::Kind::Omitted) return "off";
  std::string s;
  for (char c : p.value) s += (c == '/' || c == ' ' || c == ',') ? '+' : c;
  return s;
}

// Each run followed by its runs at the ends of the uncertain ranges.
std::vector<StudyRun> with_uncertainty(const StudySpec& study, const std::vector<StudyRun>& runs) {
  if (study.uncertainty.empty()) return runs;
  std::vector<StudyRun> out;
  for (const StudyRun& run : runs) {
    out.push_back(run);
    for (const Variant& end : study.uncertainty) {
      StudyRun r = run;
      r.name = run.name.empty() ? end.name : run.name + "_" + end.name;
      r.bound = end.name;
      r.bound_of = run.name;
      for (const auto& o : end.overrides) {
        r.bound_overrides[o.stage].push_back(o.param);
        auto& params = r.overrides[o.stage];
        params = apply_overrides(params, {o.param});
      }
      out.push_back(r);
    }
  }
  return out;
}

}  // namespace

long long study_run_count(const StudySpec& study) {
  if (!study.present()) return 0;
  long long runs = study.variants.empty() ? 1 : static_cast<long long>(study.variants.size());
  for (const auto& axis : study.matrix) {
    const auto values = static_cast<long long>(axis.values.size());
    if (values > 0 && runs > kTooManyRuns / values) return kTooManyRuns;
    runs *= values;
  }
  const auto ends = static_cast<long long>(study.uncertainty.size()) + 1;
  if (runs > kTooManyRuns / ends) return kTooManyRuns;
  return std::min(runs * ends, kTooManyRuns);
}

std::vector<StudyRun> expand_study(const StudySpec& study) {
  if (!study.present()) return {};
  std::vector<StudyRun> runs;
  if (study.variants.empty()) {
    runs.push_back({});
  } else {
    for (const auto& v : study.variants) {
      StudyRun run;
      run.name = v.name;
      for (const auto& o : v.overrides) run.overrides[o.stage].push_back(o.param);
      runs.push_back(run);
    }
  }
  for (const auto& axis : study.matrix) {
    std::vector<StudyRun> next;
    for (const auto& run : runs)
      for (const auto& value : axis.values) {
        StudyRun r = run;
        const std::string part = value.key + "-" + folder_safe(value);
        r.name = r.name.empty() ? part : r.name + "_" + part;
        auto& params = r.overrides[axis.stage];
        params = apply_overrides(params, {value});
        next.push_back(r);
      }
    runs = std::move(next);
  }
  return with_uncertainty(study, runs);
}

std::vector<Param> apply_overrides(const std::vector<Param>& base,
                                   const std::vector<Param>& overrides) {
  std::vector<Param> out = base;
  for (const auto& o : overrides) {
    bool replaced = false;
    for (auto& p : out)
      if (p.key == o.key) {
        p = o;
        replaced = true;
      }
    if (!replaced) out.push_back(o);
  }
  return out;
}

}  // namespace vesica::pipelines
