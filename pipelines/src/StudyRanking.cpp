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

std::string name_of(const StudyRow& row) {
  return row.variant.empty() ? "the run" : row.variant;
}

std::string ml(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f ml", v);
  return buf;
}

}  // namespace

std::vector<std::size_t> rank_by_capacity(const StudyReport& report) {
  std::vector<Standing> standings;
  for (const StudyRow& row : report.rows()) standings.push_back(standing_of(row));
  std::vector<std::size_t> order(standings.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return better(standings[a], standings[b]);
  });
  return order;
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
                         " cmH2O: " + name_of(best) + " (" + (b.reached ? "" : "at least ") +
                         ml(b.capacity_ml) + (b.reached ? "" : ", never reaching the limit") + ")";
  std::vector<std::string> tied;
  for (std::size_t k = 1; k < order.size(); ++k) {
    const Standing s = standing_of(report.rows()[order[k]]);
    if (!b.reached && !s.reached && s.has_curve && s.capacity_ml == b.capacity_ml)
      tied.push_back(name_of(report.rows()[order[k]]));
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
    sentence += "; smallest: " + name_of(worst) + " (" + ml(w.capacity_ml) + ")";
  if (!any_reached) sentence += "; no variant reached the limit";
  return sentence + ".";
}

}  // namespace vesica::pipelines
