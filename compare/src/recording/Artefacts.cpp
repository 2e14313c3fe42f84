#include "vesica/compare/recording/Artefacts.h"

#include <cmath>
#include <sstream>

namespace vesica::compare {
namespace {

std::string fmt(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

ArtefactFlag make_flag(const Recording& r, std::size_t i, std::string kind, std::string detail) {
  ArtefactFlag f;
  f.row = i;
  f.line = r.line.empty() ? static_cast<int>(i) + 2 : r.line[i];
  f.event = r.event.empty() ? std::string() : r.event[i];
  f.kind = std::move(kind);
  f.detail = std::move(detail);
  return f;
}

// Rise of row i above the mean of its neighbours (one-sided at the ends).
double rise(const std::vector<double>& p, std::size_t i) {
  if (p.size() < 2) return 0.0;
  if (i == 0) return p[0] - p[1];
  if (i + 1 == p.size()) return p[i] - p[i - 1];
  return p[i] - 0.5 * (p[i - 1] + p[i + 1]);
}

}  // namespace

std::vector<ArtefactFlag> find_artefacts(const Recording& r, const ArtefactOptions& o) {
  std::vector<ArtefactFlag> flags;
  const bool both = !r.pves_cmh2o.empty() && !r.pabd_cmh2o.empty();
  for (std::size_t i = 0; i < r.rows(); ++i) {
    if (both) {
      const double dves = rise(r.pves_cmh2o, i), dabd = rise(r.pabd_cmh2o, i);
      if (dves >= o.spike_cmh2o && dabd >= o.spike_cmh2o)
        flags.push_back(make_flag(
            r, i, "abdominal spike",
            "Pves +" + fmt(dves) + " and Pabd +" + fmt(dabd) + " cmH2O above their neighbours"));
    }
    if (r.has_pdet() && r.pdet_cmh2o(i) < -o.negative_pdet_cmh2o)
      flags.push_back(
          make_flag(r, i, "straining", "Pdet " + fmt(r.pdet_cmh2o(i)) + " cmH2O: Pabd above Pves"));
    if (both && !r.pdet_recorded_cmh2o.empty()) {
      const double diff = r.pdet_recorded_cmh2o[i] - (r.pves_cmh2o[i] - r.pabd_cmh2o[i]);
      if (std::abs(diff) > o.mismatch_cmh2o)
        flags.push_back(
            make_flag(r, i, "pdet mismatch",
                      "recorded Pdet differs from Pves - Pabd by " + fmt(diff) + " cmH2O"));
    }
  }
  return flags;
}

std::vector<bool> flagged_rows(const Recording& r, const std::vector<ArtefactFlag>& flags) {
  std::vector<bool> out(r.rows(), false);
  for (const auto& f : flags) out[f.row] = true;
  return out;
}

}  // namespace vesica::compare
