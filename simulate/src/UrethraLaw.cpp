#include "UrethraLaw.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {

// The least R1 (cmH2O·s/ml) of a law given in clinical units (from_clinical_units).
constexpr double kMinR1CmH2OSPerMl = 1e-6;

}  // namespace

UrethraLaw::UrethraLaw(double opening_pressure_pa, double r1_pa_s_per_m3, double r2_pa_s2_per_m6)
    : opening_pressure_(opening_pressure_pa), r1_(r1_pa_s_per_m3), r2_(r2_pa_s2_per_m6) {
  if (!(r1_ > 0.0) || !(r2_ >= 0.0))
    throw std::invalid_argument("urethra law needs R1 > 0 and R2 >= 0");
}

UrethraLaw UrethraLaw::from_clinical_units(double p_open_cmh2o, double r1_cmh2o_s_per_ml,
                                           double r2_cmh2o_s2_per_ml2) {
  // cmH2O·s/ml → Pa·s/m³ and cmH2O·s²/ml² → Pa·s²/m⁶.
  const double r1 =
      std::max(r1_cmh2o_s_per_ml, kMinR1CmH2OSPerMl) * units::kPaPerCmH2O / units::kM3PerMl;
  const double r2 = r2_cmh2o_s2_per_ml2 * units::kPaPerCmH2O / (units::kM3PerMl * units::kM3PerMl);
  return {units::pa_from_cmh2o(p_open_cmh2o), r1, r2};
}

double UrethraLaw::flow(double pressure_pa) const {
  const double dp = pressure_pa - opening_pressure_;
  if (dp <= 0.0) return 0.0;
  // The positive root of R2 Q² + R1 Q − dp = 0, written without cancellation.
  return r2_ > 0.0 ? 2.0 * dp / (r1_ + std::sqrt(r1_ * r1_ + 4.0 * r2_ * dp)) : dp / r1_;
}

double UrethraLaw::flow_derivative(double pressure_pa) const {
  if (pressure_pa - opening_pressure_ <= 0.0) return 0.0;
  return 1.0 / pressure_drop_derivative(flow(pressure_pa));
}

double UrethraLaw::pressure_drop(double flow_m3_s) const {
  return r1_ * flow_m3_s + r2_ * flow_m3_s * std::abs(flow_m3_s);
}

double UrethraLaw::pressure_drop_derivative(double flow_m3_s) const {
  return r1_ + 2.0 * r2_ * std::abs(flow_m3_s);
}

UrethraLaw UrethraLaw::with_opening_pressure(double opening_pressure_pa) const {
  return {opening_pressure_pa, r1_, r2_};
}

}  // namespace vesica::simulate
