#pragma once
// One simulated cystometry as read back from vesica-simulate's history.csv, and the study
// numbers defined on it (docs/physics.md §7). Units are those of the file's columns: volumes in
// ml, pressures in cmH2O, flow in ml/s, time in s; the study table reports them as such.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <vector>

namespace vesica::pipelines {

struct CystometryCurve {
  std::vector<double> time_s, volume_ml, pdet_cmh2o, flow_ml_s;

  std::size_t size() const { return time_s.size(); }
  // Index of the last filling row: the first row holding the largest volume. Voiding (and
  // a failed run's missing rest) come after it; holding at capacity does not add rows to
  // the filling curve because the volume stays the same.
  std::size_t filling_end() const;
};

// Reads the columns time_s, volume_ml, pdet_cmh2o and flow_ml_s (others are ignored)
// through vesica_io's history reader (vesica/io/HistoryCsv.h). Throws vesica::Error naming
// the file for a missing column or a non-numeric cell.
CystometryCurve read_history_csv(const std::filesystem::path& csv);

// Pdet where the filling curve passes `volume_ml`, linearly interpolated between rows;
// empty when filling never reached that volume.
std::optional<double> filling_pdet_at_volume(const CystometryCurve& curve, double volume_ml);

// Volume where the filling Pdet first reaches `pdet_cmh2o`, linearly interpolated; empty
// when it never does (the capacity at that pressure is then above the largest volume).
std::optional<double> filling_volume_at_pdet(const CystometryCurve& curve, double pdet_cmh2o);

// Compliance ΔV/ΔPdet (ml/cmH2O) between the start of filling and the end of filling
// (cystometric capacity); empty when Pdet did not rise.
std::optional<double> filling_compliance(const CystometryCurve& curve);

// Largest flow after the end of filling (ml/s); empty when the run never voided.
std::optional<double> voiding_qmax(const CystometryCurve& curve);

// Largest Pdet of the whole run (filling and voiding); empty for an empty curve.
std::optional<double> max_pdet(const CystometryCurve& curve);

}  // namespace vesica::pipelines
