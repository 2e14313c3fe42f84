#pragma once
// SI units inside vesica (m, Pa, s, m^3, kg); clinical units only at the edges.
// Every conversion lives here so that a factor is written once.
namespace vesica::units {

inline constexpr double kPaPerCmH2O = 98.0665;  // 1 cmH2O = 98.0665 Pa (exact, by definition)
inline constexpr double kM3PerMl = 1e-6;
inline constexpr double kMPerMm = 1e-3;
inline constexpr double kSecondsPerMinute = 60.0;
inline constexpr double kStandardGravity = 9.81;  // m/s^2, as in docs/physics.md §4

constexpr double m3_from_ml(double ml) { return ml * kM3PerMl; }
constexpr double ml_from_m3(double m3) { return m3 / kM3PerMl; }
constexpr double m_from_mm(double mm) { return mm * kMPerMm; }
constexpr double mm_from_m(double m) { return m / kMPerMm; }
constexpr double pa_from_cmh2o(double cmh2o) { return cmh2o * kPaPerCmH2O; }
constexpr double cmh2o_from_pa(double pa) { return pa / kPaPerCmH2O; }
constexpr double pa_from_kpa(double kpa) { return kpa * 1e3; }
constexpr double kpa_from_pa(double pa) { return pa * 1e-3; }
constexpr double m3s_from_mls(double ml_s) { return ml_s * kM3PerMl; }
constexpr double mls_from_m3s(double m3_s) { return m3_s / kM3PerMl; }
constexpr double m3s_from_ml_per_min(double ml_min) {
  return ml_min * kM3PerMl / kSecondsPerMinute;
}
// Voxel volumes: mm^3 -> ml.
constexpr double ml_from_mm3(double mm3) { return mm3 * 1e-3; }

}  // namespace vesica::units
