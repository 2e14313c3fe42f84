#include "cavity/UrethraLaw.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {

// The least R1 (cmH2O·s/ml) of a law given in clinical units (from_clinical_units).
constexpr double kMinR1CmH2OSPerMl = 1e-6;

}  // namespace

UrethraLaw::UrethraLaw(double opening_pressure_pa, double closing_pressure_pa,
                       double r1_pa_s_per_m3, double r2_pa_s2_per_m6, double half_open_pa)
    : opening_pressure_(opening_pressure_pa),
      closing_pressure_(closing_pressure_pa),
      r1_(r1_pa_s_per_m3),
      r2_(r2_pa_s2_per_m6),
      half_open_(half_open_pa) {
  if (!(r1_ > 0.0) || !(r2_ >= 0.0))
    throw std::invalid_argument("urethra law needs R1 > 0 and R2 >= 0");
  if (!(closing_pressure_ <= opening_pressure_) || !(half_open_ >= 0.0))
    throw std::invalid_argument("urethra law needs p_close <= p_open and p_half >= 0");
}

UrethraLaw UrethraLaw::from_clinical_units(double p_open_cmh2o, double p_close_cmh2o,
                                           double r1_cmh2o_s_per_ml, double r2_cmh2o_s2_per_ml2,
                                           double half_open_cmh2o) {
  // cmH2O·s/ml → Pa·s/m³ and cmH2O·s²/ml² → Pa·s²/m⁶.
  const double r1 =
      std::max(r1_cmh2o_s_per_ml, kMinR1CmH2OSPerMl) * units::kPaPerCmH2O / units::kM3PerMl;
  const double r2 = r2_cmh2o_s2_per_ml2 * units::kPaPerCmH2O / (units::kM3PerMl * units::kM3PerMl);
  return {units::pa_from_cmh2o(p_open_cmh2o), units::pa_from_cmh2o(p_close_cmh2o), r1, r2,
          units::pa_from_cmh2o(half_open_cmh2o)};
}

double UrethraLaw::open_lumen_flow(double dp) const {
  // The positive root of R2 q² + R1 q − Δp = 0, written without cancellation.
  return r2_ > 0.0 ? 2.0 * dp / (r1_ + std::sqrt(r1_ * r1_ + 4.0 * r2_ * dp)) : dp / r1_;
}

double UrethraLaw::flow(double pressure_pa) const {
  const double dp = pressure_pa - closing_pressure_;
  if (dp <= 0.0) return 0.0;
  return open_fraction(dp) * open_lumen_flow(dp);
}

double UrethraLaw::flow_derivative(double pressure_pa) const {
  const double dp = pressure_pa - closing_pressure_;
  if (dp <= 0.0) return 0.0;
  const double q = open_lumen_flow(dp);
  const double dq = 1.0 / (r1_ + 2.0 * r2_ * q);
  const double dphi = (1.0 - kResidualLumen) * half_open_ / ((dp + half_open_) * (dp + half_open_));
  return dphi * q + open_fraction(dp) * dq;
}

double UrethraLaw::pressure_drop(double flow_m3_s) const {
  const double Q = std::abs(flow_m3_s);
  double dp = r1_ * Q + r2_ * Q * Q;  // the rigid tube's, a lower bound otherwise
  if (half_open_ > 0.0 && Q > 0.0) {
    // flow() increases with Δp and is at most the rigid tube's: Newton inside the bracket
    // [lo, hi], bisecting whenever a step would leave it.
    double lo = dp, hi = std::max(2.0 * dp, dp + half_open_);
    while (flow(closing_pressure_ + hi) < Q) hi *= 2.0;
    dp = hi;
    for (int it = 0; it < 100; ++it) {
      const double r = flow(closing_pressure_ + dp) - Q;
      if (r > 0.0)
        hi = dp;
      else
        lo = dp;
      if (std::abs(r) <= 1e-14 * Q || hi - lo <= 1e-14 * hi) break;
      const double next = dp - r / flow_derivative(closing_pressure_ + dp);
      dp = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
    }
  }
  return flow_m3_s < 0.0 ? -dp : dp;
}

double UrethraLaw::pressure_drop_derivative(double flow_m3_s) const {
  if (half_open_ <= 0.0) return r1_ + 2.0 * r2_ * std::abs(flow_m3_s);
  const double dp = std::abs(pressure_drop(flow_m3_s));
  // At Q = 0, the residual lumen's: dQ/dΔp(0⁺) = φ0 / R1.
  const double dQ = dp > 0.0 ? flow_derivative(closing_pressure_ + dp) : kResidualLumen / r1_;
  return 1.0 / dQ;
}

UrethraLaw UrethraLaw::recovering(double half_way_fraction, double voided_fraction) const {
  if (!(half_way_fraction > 0.0 && half_way_fraction < 1.0) || !(voided_fraction > 0.0))
    return *this;
  const double m = std::log(2.0) / std::log(1.0 / half_way_fraction);
  const double risen = std::pow(std::min(voided_fraction, 1.0), m);
  return {opening_pressure_, closing_pressure_ + (opening_pressure_ - closing_pressure_) * risen,
          r1_, r2_, half_open_};
}

UrethraLaw UrethraLaw::shifted(double dp_pa) const {
  return {opening_pressure_ + dp_pa, closing_pressure_ + dp_pa, r1_, r2_, half_open_};
}

}  // namespace vesica::simulate
