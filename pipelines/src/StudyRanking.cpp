#include "vesica/pipelines/StudyRanking.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace vesica::pipelines {
namespace {

constexpr double kLimitCmh2o = 40.0;        // StudyReport's capacity read-out
constexpr double kApproachFraction = 0.75;  // "near the limit": within a quarter of it

struct Standing {
  bool has_curve = false;
  double capacity_ml = 0;  // reached, or the largest volume filled (a lower bound)
  bool reached = false;    // filling Pdet reached the limit
  double pdet500 = INFINITY, pdet300 = INFINITY, max_filling_pdet = 0;
};

Standing standing_of(const StudyRow& row) {
  Standing s;
  if (!row.curve || row.curve->size() == 0) return s;
  s.has_curve = true;
  for (const auto& [key, v] : StudyReport::values(row)) {
    if (key == "capacity_at_40cmh2o_ml" && v.value) {
      s.capacity_ml = *v.value;
      s.reached = !v.above;
    }
    if (key == "pdet_at_500ml_cmh2o" && v.value) s.pdet500 = *v.value;
    if (key == "pdet_at_300ml_cmh2o" && v.value) s.pdet300 = *v.value;
  }
  const CystometryCurve& c = *row.curve;
  for (std::size_t i = 0; i <= c.filling_end(); ++i)
    s.max_filling_pdet = std::max(s.max_filling_pdet, c.pdet_cmh2o[i]);
  return s;
}

bool better(const Standing& a, const Standing& b) {
  if (a.has_curve != b.has_curve) return a.has_curve;
  if (a.capacity_ml != b.capacity_ml) return a.capacity_ml > b.capacity_ml;
  if (a.reached != b.reached) return !a.reached;
  if (a.pdet500 != b.pdet500) return a.pdet500 < b.pdet500;
  return a.pdet300 < b.pdet300;
}

std::string ml(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f ml", v);
  return buf;
}

// Indices into `standings`, best first.
std::vector<std::size_t> ranked(const std::vector<Standing>& standings) {
  std::vector<std::size_t> order(standings.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return better(standings[a], standings[b]);
  });
  return order;
}

// Every row read at one end of the uncertainty (a row without a run at that end has no
// curve there, and ranks last).
std::vector<Standing> standings_at(const StudyReport& report, const std::string& end) {
  std::vector<Standing> standings;
  for (const StudyRow& row : report.rows()) {
    Standing s;
    for (const StudyRow* b : report.bounds_of(row))
      if (b->bound == end) s = standing_of(*b);
    standings.push_back(s);
  }
  return standings;
}

std::string listed(const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t i = 0; i < names.size(); ++i)
    s += (i ? (i + 1 == names.size() ? " and " : ", ") : "") + names[i];
  return s;
}

}  // namespace

std::vector<std::size_t> rank_by_capacity(const StudyReport& report) {
  std::vector<Standing> standings;
  for (const StudyRow& row : report.rows()) standings.push_back(standing_of(row));
  return ranked(standings);
}

std::string robustness_answer(const StudyReport& report) {
  const std::vector<std::string>& ends = report.uncertainty_ends();
  const std::vector<std::size_t> order = rank_by_capacity(report);
  if (ends.empty() || order.empty()) return "";
  const std::string best = report.label(report.rows()[order.front()]);
  std::vector<std::string> other_first, same_order, missing;
  for (const std::string& end : ends) {
    const std::vector<Standing> at = standings_at(report, end);
    if (!at[order.front()].has_curve) {
      missing.push_back(end);
      continue;
    }
    const std::vector<std::size_t> o = ranked(at);
    if (o.front() != order.front())
      other_first.push_back(report.label(report.rows()[o.front()]) + " at the " + end + " end");
    else if (o == order)
      same_order.push_back(end);
  }
  if (!missing.empty())
    return "Not known whether the ranking holds across the wall's uncertainty: " + best +
           " has no run at the " + listed(missing) + " end.";
  if (!other_first.empty())
    return "Not robust to the wall's uncertainty: " + best + " ranks first as given, but " +
           listed(other_first) + ".";
  return "Robust to the wall's uncertainty: " + best + " ranks first at the " + listed(ends) +
         " end" + (ends.size() > 1 ? "s" : "") + " of its ranges too" +
         (same_order.size() == ends.size() ? ", and the whole order is the same"
                                           : "; the order below it changes") +
         ".";
}

std::string capacity_answer(const StudyReport& report) {
  const std::vector<std::size_t> order = rank_by_capacity(report);
  if (order.empty() || !standing_of(report.rows()[order.front()]).has_curve) return "";
  double highest = 0, smallest_filled = INFINITY;
  bool any_reached = false;
  for (const StudyRow& row : report.rows()) {
    const Standing s = standing_of(row);
    if (!s.has_curve) continue;
    highest = std::max(highest, s.max_filling_pdet);
    any_reached = any_reached || s.reached;
    smallest_filled = std::min(smallest_filled, s.capacity_ml);
  }
  char limit[16];
  std::snprintf(limit, sizeof limit, "%.0f", kLimitCmh2o);
  if (highest < kApproachFraction * kLimitCmh2o) {
    char p[16];
    std::snprintf(p, sizeof p, "%.1f", highest);
    return std::string("No variant approached the ") + limit +
           " cmH2O limit: the highest filling Pdet of any was " + p +
           " cmH2O, and every pouch held at least " + ml(smallest_filled) +
           " below it; the ranking follows Pdet at 500 ml.";
  }
  const StudyRow& best = report.rows()[order.front()];
  const Standing b = standing_of(best);
  std::string sentence = std::string("Largest capacity under ") + limit +
                         " cmH2O: " + report.label(best) + " (" + (b.reached ? "" : "at least ") +
                         ml(b.capacity_ml) + (b.reached ? "" : ", never reaching the limit") + ")";
  std::vector<std::string> tied;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Standing s = standing_of(report.rows()[order[k]]);
    if (!b.reached && !s.reached && s.has_curve && s.capacity_ml == b.capacity_ml)
      tied.push_back(report.label(report.rows()[order[k]]));
  }
  if (!tied.empty()) {
    sentence += ", as did ";
    for (std::size_t i = 0; i < tied.size(); ++i)
      sentence += (i ? (i + 1 == tied.size() ? " and " : ", ") : "") + tied[i];
    sentence += " (ranked by their lower Pdet at 500 ml)";
  }
  const StudyRow& worst = report.rows()[order.back()];
  const Standing w = standing_of(worst);
  if (w.has_curve && order.size() > 1 && w.reached)
    sentence += "; smallest: " + report.label(worst) + " (" + ml(w.capacity_ml) + ")";
  if (!any_reached) sentence += "; no variant reached the limit";
  return sentence + ".";
}

}  // namespace vesica::pipelines
