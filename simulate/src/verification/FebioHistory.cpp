// The load histories of an FEBio export (FebioExport.h): the transmural pressure along
// time as vesica computed it. Pressures in Pa, times in s.
#include "vesica/simulate/verification/FebioExport.h"

#include <algorithm>
#include <string>

#include "verification/FebioText.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {

// How much longer than the slowest relaxation the settling ramp lasts: the branches' stress
// left at its end is about beta tau / T of the elastic one (1e-4 of it), as good as relaxed.
constexpr double kSettleRelaxations = 1e3;
constexpr int kSettleIntervals = 10;

}  // namespace

FebioLoadHistory febio_verification_history(const VerificationResult& result) {
  if (result.rows.size() < 2)
    usage_error(
        "--export-feb: the verification converged no step, so there is no pressure to "
        "load FEBio's wall with");
  // Up to the first highest pressure: FEBio follows the pressure, which past a limit point
  // of volume steps falls again.
  std::size_t last = 1;
  for (std::size_t i = 1; i < result.rows.size(); ++i)
    if (result.rows[i].pressure_pa > result.rows[last].pressure_pa) last = i;
  FebioLoadHistory h;
  h.instantaneous = true;
  for (std::size_t i = 0; i <= last; ++i) {
    h.time_s.push_back(static_cast<double>(i));
    h.pressure_pa.push_back(result.rows[i].pressure_pa);
  }
  h.description = "the pressures of vesica's " + std::to_string(last) +
                  " verification steps (pressure_stretch.csv), one per unit of time";
  if (last + 1 < result.rows.size())
    h.description += ", up to the highest, " + febio_message_number(result.rows[last].pressure_pa) +
                     " Pa: FEBio follows a pressure, which falls past the limit point";
  return h;
}

FebioLoadHistory febio_filling_history(const std::vector<io::HistoryRow>& history,
                                       const ProtocolSettings& protocol,
                                       const MaterialCard& material) {
  const double fill_s =
      (protocol.capacity_ml - protocol.start_ml) / protocol.fill_rate_ml_min * 60.0;
  const double end_s = fill_s + protocol.hold_s;
  double slowest = 0.0;
  for (const MaxwellBranchValues& b : material.branches) slowest = std::max(slowest, b.tau_s);
  const double settle_s = slowest > 0.0 ? kSettleRelaxations * slowest : 1.0;
  FebioLoadHistory h;
  for (const io::HistoryRow& row : history) {
    if (row.time_s > end_s * (1.0 + 1e-12) + 1e-9) break;  // voiding
    const double t = settle_s + row.time_s;
    if (!h.time_s.empty() && !(t > h.time_s.back())) continue;
    if (h.time_s.empty())  // the settling: a ramp to the first row's pressure
      for (int i = 0; i < kSettleIntervals; ++i) {
        h.time_s.push_back(settle_s * i / kSettleIntervals);
        h.pressure_pa.push_back(units::pa_from_cmh2o(row.pdet_cmh2o) * i / kSettleIntervals);
      }
    h.time_s.push_back(t);
    h.pressure_pa.push_back(units::pa_from_cmh2o(row.pdet_cmh2o));
  }
  if (h.time_s.size() < kSettleIntervals + 2)
    usage_error("--export-feb: the cystometry recorded no filling step to load FEBio's wall with");
  h.description = "vesica's settling from the stress-free wall to the start of filling (" +
                  febio_message_number(protocol.start_ml) + " ml), relaxed, as a ramp over " +
                  febio_message_number(settle_s) + " s; then its filling to " +
                  febio_message_number(protocol.capacity_ml) + " ml at " +
                  febio_message_number(protocol.fill_rate_ml_min) +
                  " ml/min and hold: Pdet = Pves - Pabd at the times of history.csv (+ " +
                  febio_message_number(settle_s) + " s)";
  return h;
}

}  // namespace vesica::simulate
