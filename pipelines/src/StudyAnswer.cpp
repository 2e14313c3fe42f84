#include "vesica/pipelines/StudyAnswer.h"

#include <sstream>

namespace vesica::pipelines {
namespace {

enum class Holds { yes, no, unknown };

Holds check(const StudyLimit& l, const StudyValue& v) {
  if (!v.value) return Holds::unknown;
  const double x = *v.value;
  if (v.above) {  // only known to exceed x
    if (l.max && x >= *l.max) return Holds::no;
    if (l.max) return Holds::unknown;
    return x >= *l.min ? Holds::yes : Holds::unknown;
  }
  if (l.min && x < *l.min) return Holds::no;
  if (l.max && x > *l.max) return Holds::no;
  return Holds::yes;
}

}  // namespace

std::string answer(const std::vector<StudyLimit>& limits, const StudyValues& values) {
  if (limits.empty()) return "";
  bool unknown = false;
  for (const StudyLimit& l : limits) {
    StudyValue v;
    for (const auto& [key, value] : values)
      if (key == l.metric) v = value;
    const Holds h = check(l, v);
    if (h == Holds::no) return "fail";
    unknown = unknown || h == Holds::unknown;
  }
  return unknown ? "" : "pass";
}

std::string limit_text(const StudyLimit& l) {
  const StudyMetric* m = find_study_metric(l.metric);
  std::ostringstream o;
  o << (m ? m->label : l.metric);
  if (l.min && l.max)
    o << " between " << *l.min << " and " << *l.max;
  else if (l.min)
    o << " >= " << *l.min;
  else
    o << " <= " << *l.max;
  if (m) o << ' ' << m->unit;
  return o.str();
}

}  // namespace vesica::pipelines
