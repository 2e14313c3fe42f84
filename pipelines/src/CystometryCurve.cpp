#include "vesica/pipelines/CystometryCurve.h"

#include <algorithm>

#include "vesica/io/HistoryCsv.h"

namespace vesica::pipelines {
namespace {

// Linear interpolation of y at x between rows a and b (x between x[a] and x[b]).
double interpolate(double xa, double xb, double ya, double yb, double x) {
  return xb == xa ? yb : ya + (yb - ya) * (x - xa) / (xb - xa);
}

}  // namespace

std::size_t CystometryCurve::filling_end() const {
  if (volume_ml.empty()) return 0;
  return static_cast<std::size_t>(std::max_element(volume_ml.begin(), volume_ml.end()) -
                                  volume_ml.begin());
}

CystometryCurve read_history_csv(const std::filesystem::path& csv) {
  const io::Recording history = io::read_history_csv(csv);
  CystometryCurve c;
  c.time_s = history.time_s;
  c.volume_ml = history.volume_ml;
  c.flow_ml_s = history.flow_ml_s;
  c.pdet_cmh2o.resize(history.rows());
  for (std::size_t i = 0; i < history.rows(); ++i) c.pdet_cmh2o[i] = history.pdet_cmh2o(i);
  return c;
}

std::optional<double> filling_pdet_at_volume(const CystometryCurve& curve, double volume_ml) {
  if (curve.size() == 0) return std::nullopt;
  const auto& V = curve.volume_ml;
  const auto& P = curve.pdet_cmh2o;
  if (V[0] >= volume_ml) return V[0] == volume_ml ? std::optional<double>(P[0]) : std::nullopt;
  // Rounding in history.csv may leave the last filling row a hair below the target.
  const double tolerance = 1e-6 * volume_ml;
  const std::size_t end = curve.filling_end();
  for (std::size_t i = 1; i <= end; ++i)
    if (V[i] >= volume_ml - tolerance)
      return interpolate(V[i - 1], V[i], P[i - 1], P[i], std::min(volume_ml, V[i]));
  return std::nullopt;
}

std::optional<double> filling_volume_at_pdet(const CystometryCurve& curve, double pdet_cmh2o) {
  if (curve.size() == 0) return std::nullopt;
  const auto& V = curve.volume_ml;
  const auto& P = curve.pdet_cmh2o;
  if (P[0] >= pdet_cmh2o) return V[0];
  const std::size_t end = curve.filling_end();
  for (std::size_t i = 1; i <= end; ++i)
    if (P[i] >= pdet_cmh2o) return interpolate(P[i - 1], P[i], V[i - 1], V[i], pdet_cmh2o);
  return std::nullopt;
}

std::optional<double> filling_compliance(const CystometryCurve& curve) {
  if (curve.size() == 0) return std::nullopt;
  const std::size_t end = curve.filling_end();
  const double dp = curve.pdet_cmh2o[end] - curve.pdet_cmh2o[0];
  if (!(dp > 0.0)) return std::nullopt;
  return (curve.volume_ml[end] - curve.volume_ml[0]) / dp;
}

std::optional<double> voiding_qmax(const CystometryCurve& curve) {
  const std::size_t end = curve.filling_end();
  if (end + 1 >= curve.size()) return std::nullopt;
  return *std::max_element(curve.flow_ml_s.begin() + static_cast<long>(end) + 1,
                           curve.flow_ml_s.end());
}

std::optional<double> max_pdet(const CystometryCurve& curve) {
  if (curve.size() == 0) return std::nullopt;
  return *std::max_element(curve.pdet_cmh2o.begin(), curve.pdet_cmh2o.end());
}

}  // namespace vesica::pipelines
