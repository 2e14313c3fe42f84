// The urethra law (docs/physics.md §5) against tables worked by hand. The rigid urethra
// opening and closing at 20 cmH2O, p − 20 = R1 Q + R2 Q² with R1 = 0.2 cmH2O·s/ml,
// R2 = 0.05 cmH2O·s²/ml²: a pressure p above it gives Q² + 4 Q − 20 (p − 20) = 0, so
// Q = −2 + √(4 + 20 (p − 20)) ml/s, and dQ/dp = 1 / (R1 + 2 R2 Q) ml/s per cmH2O:
//   p = 20.25 → Q = −2 + √9   = 1 ml/s,               dQ/dp = 1 / 0.3       = 3.33333…
//   p = 30    → Q = −2 + √204 = 12.2828568570857 ml/s, dQ/dp = 1 / 1.42828… = 0.700140…
//   p = 40    → Q = −2 + √404 = 18.0997512422418 ml/s, dQ/dp = 1 / 2.00997… = 0.497519…
// and no flow at or below p_open. The collapsible urethra closing at p_close = 10 cmH2O,
// half open p_half = 5 cmH2O above it, R1 = 0.2, R2 = 0.02: at Δp = p − p_close the open
// lumen passes q with 0.02 q² + 0.2 q = Δp, q = (−0.2 + √(0.04 + 0.08 Δp)) / 0.04, the
// lumen's open fraction is φ = (Δp + 0.05·5)/(Δp + 5), and Q = φ q:
//   Δp = 1  → q = 3.66025403784439, φ = 0.208333…, Q = 0.762552924550914 ml/s
//   Δp = 10 → q = 17.9128784747792, φ = 0.683333…, Q = 12.2404669577658 ml/s
// The law works in SI; the tables are in clinical units.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "cavity/UrethraLaw.h"

using vesica::simulate::UrethraLaw;

namespace {

constexpr double kPaPerCmH2O = 98.0665, kM3PerMl = 1e-6;

double ml_s(double m3_s) {
  return m3_s / kM3PerMl;
}
double pa(double cmh2o) {
  return cmh2o * kPaPerCmH2O;
}
// dQ/dp from m³/(s·Pa) to ml/s per cmH2O.
double ml_s_per_cmh2o(double si) {
  return si * kPaPerCmH2O / kM3PerMl;
}

const UrethraLaw& clinical_law() {
  static const UrethraLaw law = UrethraLaw::from_clinical_units(20.0, 20.0, 0.2, 0.05);
  return law;
}

}  // namespace

TEST(UrethraLaw, FlowMatchesTheHandWorkedTable) {
  const UrethraLaw& law = clinical_law();
  EXPECT_NEAR(law.opening_pressure(), pa(20.0), 1e-12);
  EXPECT_NEAR(ml_s(law.flow(pa(20.25))), 1.0, 1e-12);
  EXPECT_NEAR(ml_s(law.flow(pa(30.0))), 12.2828568570857, 1e-11);
  EXPECT_NEAR(ml_s(law.flow(pa(40.0))), 18.0997512422418, 1e-11);
  EXPECT_NEAR(ml_s_per_cmh2o(law.flow_derivative(pa(20.25))), 1.0 / 0.3, 1e-12);
  EXPECT_NEAR(ml_s_per_cmh2o(law.flow_derivative(pa(30.0))), 1.0 / (0.2 + 0.1 * 12.2828568570857),
              1e-12);
  EXPECT_NEAR(ml_s_per_cmh2o(law.flow_derivative(pa(40.0))), 1.0 / (0.2 + 0.1 * 18.0997512422418),
              1e-12);
}

TEST(UrethraLaw, NoFlowUntilTheUrethraOpens) {
  const UrethraLaw& law = clinical_law();
  for (double p_cmh2o : {-5.0, 0.0, 10.0, 20.0}) {
    EXPECT_EQ(law.flow(pa(p_cmh2o)), 0.0) << p_cmh2o;
    EXPECT_EQ(law.flow_derivative(pa(p_cmh2o)), 0.0) << p_cmh2o;
  }
}

// The pressure form of level 2 and the flow form of level 1 are the same law: the pressure
// drop of 1 ml/s is 0.2 + 0.05 = 0.25 cmH2O, of a 1 ml/s backflow −0.25 cmH2O.
TEST(UrethraLaw, PressureFormInvertsTheFlowForm) {
  const UrethraLaw& law = clinical_law();
  EXPECT_NEAR(law.pressure_drop(1.0 * kM3PerMl) / kPaPerCmH2O, 0.25, 1e-12);
  EXPECT_NEAR(law.pressure_drop(-1.0 * kM3PerMl) / kPaPerCmH2O, -0.25, 1e-12);
  EXPECT_NEAR(law.pressure_drop_derivative(1.0 * kM3PerMl) * kM3PerMl / kPaPerCmH2O, 0.3, 1e-12);
  for (double p_cmh2o : {20.25, 30.0, 40.0}) {
    const double q = law.flow(pa(p_cmh2o));
    EXPECT_NEAR(law.closing_pressure() + law.pressure_drop(q), pa(p_cmh2o), 1e-9) << p_cmh2o;
  }
}

// Without the quadratic term the law is Ohm's: Q = (p − p_open) / R1 = 10 / 0.5 = 20 ml/s.
TEST(UrethraLaw, LinearLawIsOhmic) {
  const UrethraLaw law = UrethraLaw::from_clinical_units(20.0, 20.0, 0.5, 0.0);
  EXPECT_NEAR(ml_s(law.flow(pa(30.0))), 20.0, 1e-12);
  EXPECT_NEAR(ml_s_per_cmh2o(law.flow_derivative(pa(30.0))), 2.0, 1e-12);
}

// A resistance of zero is raised to 1e-6 cmH2O·s/ml, where dQ/dp stays finite at p_open.
TEST(UrethraLaw, ZeroLinearResistanceKeepsAFiniteSlope) {
  const UrethraLaw law = UrethraLaw::from_clinical_units(20.0, 20.0, 0.0, 0.05);
  EXPECT_NEAR(law.r1() * kM3PerMl / kPaPerCmH2O, 1e-6, 1e-18);
  EXPECT_TRUE(std::isfinite(law.flow_derivative(pa(20.0) + 1e-9)));
}

TEST(UrethraLaw, NonPositiveResistanceAndClosingAboveOpeningAreRefused) {
  EXPECT_THROW(UrethraLaw(0.0, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(UrethraLaw(0.0, 1.0, -1.0), std::invalid_argument);
  EXPECT_THROW(UrethraLaw(10.0, 20.0, 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(UrethraLaw(20.0, 10.0, 1.0, 0.0, -1.0), std::invalid_argument);
}

namespace {

const UrethraLaw& collapsible_law() {
  static const UrethraLaw law = UrethraLaw::from_clinical_units(20.0, 10.0, 0.2, 0.02, 5.0);
  return law;
}

}  // namespace

// A collapsible urethra opens at 20 cmH2O and passes flow down to its closing pressure,
// 10 cmH2O: the table above, and nothing at or below p_close.
TEST(UrethraLaw, CollapsibleUrethraFlowsBetweenClosingAndOpeningAsWorkedByHand) {
  const UrethraLaw& law = collapsible_law();
  EXPECT_NEAR(law.opening_pressure(), pa(20.0), 1e-12);
  EXPECT_NEAR(law.closing_pressure(), pa(10.0), 1e-12);
  EXPECT_NEAR(ml_s(law.flow(pa(11.0))), 0.762552924550914, 1e-12);
  EXPECT_NEAR(ml_s(law.flow(pa(20.0))), 12.2404669577658, 1e-11);
  EXPECT_EQ(law.flow(pa(10.0)), 0.0);
  EXPECT_EQ(law.flow(pa(5.0)), 0.0);
  // dQ/dp against central differences, and its limit φ0/R1 = 0.25 ml/s per cmH2O as the
  // lumen closes.
  for (double p_cmh2o : {10.5, 11.0, 20.0, 35.0}) {
    const double h = 1e-4 * kPaPerCmH2O;
    const double fd = (law.flow(pa(p_cmh2o) + h) - law.flow(pa(p_cmh2o) - h)) / (2.0 * h);
    EXPECT_NEAR(law.flow_derivative(pa(p_cmh2o)), fd, 1e-6 * std::abs(fd)) << p_cmh2o;
  }
  EXPECT_NEAR(ml_s_per_cmh2o(law.flow_derivative(pa(10.0) + 1e-9)), 0.05 / 0.2, 1e-6);
  // A collapsed lumen passes less than the rigid one at every pressure.
  const UrethraLaw rigid = UrethraLaw::from_clinical_units(20.0, 10.0, 0.2, 0.02);
  for (double p_cmh2o : {11.0, 20.0, 60.0})
    EXPECT_LT(law.flow(pa(p_cmh2o)), rigid.flow(pa(p_cmh2o))) << p_cmh2o;
}

// Level 2's pressure form inverts the collapsible law too, odd in Q, with the slope
// 1/(dQ/dp) and R1/φ0 = 4 cmH2O per ml/s at Q = 0.
TEST(UrethraLaw, CollapsibleUrethraPressureFormInvertsItsFlowForm) {
  const UrethraLaw& law = collapsible_law();
  EXPECT_NEAR(law.pressure_drop(12.2404669577658 * kM3PerMl) / kPaPerCmH2O, 10.0, 1e-9);
  EXPECT_NEAR(law.pressure_drop(-0.762552924550914 * kM3PerMl) / kPaPerCmH2O, -1.0, 1e-9);
  for (double p_cmh2o : {10.2, 12.0, 30.0}) {
    const double q = law.flow(pa(p_cmh2o));
    EXPECT_NEAR(law.closing_pressure() + law.pressure_drop(q), pa(p_cmh2o), 1e-9) << p_cmh2o;
    EXPECT_NEAR(law.pressure_drop_derivative(q) * law.flow_derivative(pa(p_cmh2o)), 1.0, 1e-9);
  }
  EXPECT_NEAR(law.pressure_drop_derivative(0.0) * kM3PerMl / kPaPerCmH2O, 4.0, 1e-9);
  // Both pressures move with the datum.
  const UrethraLaw shifted = law.shifted(pa(3.0));
  EXPECT_NEAR(shifted.opening_pressure(), pa(23.0), 1e-9);
  EXPECT_NEAR(shifted.flow(pa(23.0)), law.flow(pa(20.0)), 1e-15);
}

// The recovering sphincter (docs/physics.md §5, the sphincter's recovery) by hand: opened
// at 20 and closing at 10 cmH2O. Half-way at half voided, it rises linearly: 12.5 cmH2O at a
// quarter voided, 15 at half; half-way at a quarter voided, m = ln 2 / ln 4 = ½: 15 cmH2O at
// a quarter, 10 + 10 √0.5 = 17.0711 at half. Empty, it closes where it opened; the open
// lumen's law is the same one measured from the risen closing pressure.
TEST(UrethraLaw, ARecoveringSphincterRaisesTheClosingPressureTowardsTheOpeningOne) {
  const UrethraLaw& law = collapsible_law();
  EXPECT_NEAR(law.recovering(0.5, 0.25).closing_pressure(), pa(12.5), 1e-9);
  EXPECT_NEAR(law.recovering(0.5, 0.5).closing_pressure(), pa(15.0), 1e-9);
  EXPECT_NEAR(law.recovering(0.25, 0.25).closing_pressure(), pa(15.0), 1e-9);
  EXPECT_NEAR(law.recovering(0.25, 0.5).closing_pressure(), pa(10.0 + 10.0 * std::sqrt(0.5)), 1e-9);
  EXPECT_NEAR(law.recovering(0.5, 1.0).closing_pressure(), pa(20.0), 1e-9);
  const UrethraLaw half = law.recovering(0.5, 0.5);
  EXPECT_NEAR(half.opening_pressure(), pa(20.0), 1e-12);
  EXPECT_EQ(half.flow(pa(14.9)), 0.0);
  EXPECT_NEAR(half.flow(pa(16.0)), law.flow(pa(11.0)), 1e-15);
  // No recovery (half-way only when empty), or nothing voided yet: the law itself.
  EXPECT_EQ(law.recovering(1.0, 0.9).closing_pressure(), law.closing_pressure());
  EXPECT_EQ(law.recovering(0.5, 0.0).closing_pressure(), law.closing_pressure());
}
