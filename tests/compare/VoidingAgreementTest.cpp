// The voiding read-outs of a calibration: the aligned flow correlation against values
// worked out by hand, and the voiding series' rules for a run whose flow ends early.
#include <cmath>

#include <gtest/gtest.h>

#include "vesica/compare/analysis/VoidingAgreement.h"
#include "vesica/compare/calibration/CalibrationTargets.h"

namespace vc = vesica::compare;

TEST(VoidingAgreement, UncorrelatedShapesOnTheHalfSecondGrid) {
  // grid 0, 0.5, 1, 1.5, 2 s: a = 0 1 2 1 0, b = 0 .5 1 1.5 2; centred, Σ da db = 0
  const vc::Curve a{{0, 1, 2}, {0, 2, 0}}, b{{0, 2}, {0, 2}};
  EXPECT_NEAR(*vc::aligned_flow_correlation(a, b), 0.0, 1e-12);
  EXPECT_NEAR(*vc::aligned_flow_correlation(a, a), 1.0, 1e-12);
}

TEST(VoidingAgreement, AFlowThatEndsEarlyIsZeroAfterwards) {
  // a = 0 1 2 3 4 (mean 2), b = 0 1 2 0 0 (its flow ends at 1 s; mean 0.6):
  // Σ da db = 1.2 - 0.4 + 0 - 0.6 - 1.2 = -1, Σ da² = 10, Σ db² = 3.2, so r = -1/√32
  const vc::Curve a{{0, 2}, {0, 4}}, b{{0, 1}, {0, 2}};
  EXPECT_NEAR(*vc::aligned_flow_correlation(a, b), -1.0 / std::sqrt(32.0), 1e-12);
  EXPECT_FALSE(vc::aligned_flow_correlation(a, vc::Curve{{0, 2}, {3, 3}}));  // constant
}

namespace {

// A recording that fills 100 -> 200 ml in 100 s, then voids at 10 ml/s for `void_s`
// seconds with Pdet 30 cmH2O while flowing.
vc::ModelRun voiding_run(double void_s, bool completed) {
  vc::ModelRun run;
  auto& r = run.recording;
  double voided = 0;
  for (int t = 0; t <= 100 + static_cast<int>(void_s) + 1; ++t) {
    const bool flowing = t > 100 && t <= 100 + void_s;
    if (flowing) voided += 10;
    r.time_s.push_back(t);
    r.volume_ml.push_back(std::min(100.0 + t, 200.0) - voided);
    r.infused_ml.push_back(std::min(100.0 + t, 200.0) - 100);
    r.pdet_recorded_cmh2o.push_back(flowing ? 30 : 5);
    r.flow_ml_s.push_back(flowing ? 10 : 0);
    r.voided_ml.push_back(voided);
  }
  run.completed = completed;
  if (!completed) run.failure = "step failed";
  return run;
}

}  // namespace

TEST(VoidingTargets, AfterACompletedRunsFlowStoppedItsFlowIsZeroAndItsPressureUncompared) {
  vc::CalibrationTargets t;
  vc::TargetSeries q;
  q.name = "voiding flow";
  q.quantity = vc::Quantity::Flow;
  q.abscissa = vc::Abscissa::TimeSinceFlowOnset;
  q.x = {0, 5, 15};
  q.y = {0, 10, 8};
  vc::TargetSeries p = q;
  p.name = "voiding Pdet";
  p.quantity = vc::Quantity::Pdet;
  p.y = {5, 30, 25};
  t.series = {q, p};
  t.voiding = true;
  // the run's flow lasts 10 s: at 15 s its flow is 0 (residual -8), its Pdet not compared
  const auto e = vc::evaluate(t, voiding_run(10, true));
  ASSERT_FALSE(e.failed) << e.failure;
  EXPECT_NEAR(e.residuals[1], 0.0, 1e-12);
  EXPECT_NEAR(e.residuals[2], -8.0, 1e-12);
  EXPECT_TRUE(e.compared[4]);
  EXPECT_FALSE(e.compared[5]);
  // the same run stopped by a failure before 15 s is a failed evaluation
  const auto f = vc::evaluate(t, voiding_run(10, false));
  EXPECT_TRUE(f.failed);
  EXPECT_NE(f.failure.find("before the data's last reading at 15 s"), std::string::npos)
      << f.failure;
}
