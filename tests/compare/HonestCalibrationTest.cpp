// The calibration says what happened: runs that stop short are failed evaluations (never
// extrapolated), parameters the data cannot move are reported as such, every fit is judged
// against the constant and straight-line baselines, the fitted model must reach the end of
// the data, and a calibration whose every run failed says so. Models with known answers
// (FitTestModels.h) stand in for the simulator.
#include <algorithm>

#include <gtest/gtest.h>

#include "FitTestModels.h"
#include "vesica/compare/analysis/Baselines.h"
#include "vesica/compare/calibration/TwoStageFit.h"

namespace vc = vesica::compare;
using vesica::test::filling_run;
using vesica::test::measured_filling;

namespace {

// Pdet = a (V - 50)/100 + b: a straight line with two parameters.
double linear_law(const std::vector<double>& p, double v) {
  return p[0] * (v - 50) / 100 + p[1];
}

vc::FitParameter parameter(const char* name, double initial) {
  return {name, "-", initial, 1e-3, 1e3, false};
}

vc::FitProblem linear_problem(const std::function<double(double)>& measured) {
  vc::FitProblem pb;
  pb.targets = vc::filling_targets(measured_filling(measured), 50, 350);
  pb.parameters = {parameter("a", 1.0), parameter("b", 1.0)};
  pb.model = [](const std::vector<double>& p) { return filling_run(linear_law, p, 350); };
  return pb;
}

}  // namespace

TEST(Baselines, ConstantAndLineRmseOfAHandWorkedTable) {
  // mean 1.5: constant RMSE sqrt(5/4); line slope 4/5, residual sum 5 - 16/5 = 1.8
  const auto b = vc::baseline_rmse({0, 1, 2, 3}, {0, 2, 1, 3});
  EXPECT_NEAR(b.constant, std::sqrt(5.0 / 4.0), 1e-12);
  EXPECT_NEAR(b.line, std::sqrt(1.8 / 4.0), 1e-12);
}

TEST(HonestCalibration, ARunThatStopsBeforeTheLastVolumeIsAFailedEvaluation) {
  const auto targets = vc::filling_targets(measured_filling([](double) { return 3.0; }), 50, 350);
  const auto run = filling_run(linear_law, {1.0, 3.0}, 350, 200);  // stops at 200 ml
  const vc::Evaluation e = vc::evaluate(targets, run);
  EXPECT_TRUE(e.failed);
  EXPECT_NE(e.failure.find("stopped at 200 ml"), std::string::npos) << e.failure;
  // every residual is the penalty: none is read off the run's last value
  for (Eigen::Index i = 0; i < e.residuals.size(); ++i)
    EXPECT_EQ(e.residuals[i], vc::kFailedResidual);
  // the same run to capacity is compared reading by reading: 3 + (V-50)/100 - 3
  const vc::Evaluation full = vc::evaluate(targets, filling_run(linear_law, {1.0, 3.0}, 350));
  ASSERT_FALSE(full.failed);
  EXPECT_NEAR(full.residuals[4], (150.0 - 50) / 100, 1e-12);  // the 150 ml reading
}

TEST(HonestCalibration, RecoversBothParametersOfAStraightLineWithIntervals) {
  auto pb = linear_problem([](double v) { return 2.0 * (v - 50) / 100 + 1.5; });
  const auto fit = vc::fit_parameters(pb).result;
  ASSERT_EQ(fit.parameters.size(), 2u);
  EXPECT_NEAR(fit.parameters[0].value, 2.0, 1e-3);
  EXPECT_NEAR(fit.parameters[1].value, 1.5, 1e-3);
  for (const auto& p : fit.parameters) {
    EXPECT_TRUE(p.identifiable) << p.name << ": " << p.note;
    EXPECT_LT(p.ci_low, p.value);
    EXPECT_GT(p.ci_high, p.value);
  }
  // a perfect line equals the line baseline: not "a fit"
  EXPECT_FALSE(fit.fitted);
  EXPECT_NE(fit.status.find("no better than a straight line"), std::string::npos) << fit.status;
}

TEST(HonestCalibration, AParameterTheDataDoNotMoveIsNotIdentifiableAndSpansItsRange) {
  // The model ignores its second parameter: its interval is the search range, not zero.
  vc::FitProblem pb =
      linear_problem([](double v) { return 0.02 * (v - 50) + 0.001 * v * v / 100; });
  pb.model = [](const std::vector<double>& p) {
    return filling_run([](const std::vector<double>& q, double v) { return q[0] * (v - 50) / 100; },
                       p, 350);
  };
  const auto fit = vc::fit_parameters(pb).result;
  const auto& ignored = fit.parameters[1];
  EXPECT_FALSE(ignored.identifiable);
  EXPECT_NE(ignored.note.find("do not depend"), std::string::npos) << ignored.note;
  EXPECT_DOUBLE_EQ(ignored.ci_low, 1e-3);
  EXPECT_DOUBLE_EQ(ignored.ci_high, 1e3);
  EXPECT_TRUE(fit.parameters[0].identifiable) << fit.parameters[0].note;
}

TEST(HonestCalibration, OnlyTheProductOfTwoParametersIsDetermined) {
  vc::FitProblem pb = linear_problem([](double v) { return 3.0 * (v - 50) / 100; });
  pb.model = [](const std::vector<double>& p) {
    return filling_run(
        [](const std::vector<double>& q, double v) { return q[0] * q[1] * (v - 50) / 100; }, p,
        350);
  };
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_NEAR(fit.parameters[0].value * fit.parameters[1].value, 3.0, 1e-3);
  for (const auto& p : fit.parameters) {
    EXPECT_FALSE(p.identifiable) << p.name;
    EXPECT_NE(p.note.find("combination"), std::string::npos) << p.note;
  }
}

TEST(HonestCalibration, AModelThatBeatsTheLineIsAFit) {
  // Measured: a late rise the quadratic model follows and a line cannot.
  auto curve = [](double v) { return 2.0 + 1e-4 * (v - 50) * (v - 50); };
  vc::FitProblem pb = linear_problem(curve);
  pb.model = [](const std::vector<double>& p) {
    return filling_run([](const std::vector<double>& q,
                          double v) { return q[1] + q[0] * 1e-4 * (v - 50) * (v - 50); },
                       p, 350);
  };
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_TRUE(fit.fitted) << fit.status;
  ASSERT_EQ(fit.series.size(), 1u);
  EXPECT_LT(fit.series[0].rmse, 1e-3);
  EXPECT_GT(fit.series[0].line_rmse, 0.3);  // the best line misses the curvature
  EXPECT_NE(fit.status.find("straight line"), std::string::npos) << fit.status;
}

TEST(HonestCalibration, FailedTrialsArePenalisedNotExtrapolated) {
  // The model runs to capacity only for a < 2.5: the data (a = 3) are out of its reach, so
  // the best it can do is a run that reaches the end, and runs beyond a = 2.5 count as failed.
  vc::FitProblem pb = linear_problem([](double v) { return 3.0 * (v - 50) / 100; });
  pb.parameters = {parameter("a", 1.0)};
  pb.model = [](const std::vector<double>& p) {
    const double stop = p[0] < 2.5 ? 1e9 : 200;
    return filling_run([](const std::vector<double>& q, double v) { return q[0] * (v - 50) / 100; },
                       p, 350, stop);
  };
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_LT(fit.parameters[0].value, 2.5);
  EXPECT_GT(fit.failed_simulations, 0);
  bool counted = false;
  for (const auto& n : fit.notes) counted |= n.find("failed before the end") != std::string::npos;
  EXPECT_TRUE(counted);
}

TEST(HonestCalibration, WhenEveryRunFailsTheResultSaysSo) {
  vc::FitProblem pb = linear_problem([](double v) { return 3.0 * (v - 50) / 100; });
  pb.model = [](const std::vector<double>& p) { return filling_run(linear_law, p, 350, 120); };
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_FALSE(fit.fitted);
  EXPECT_NE(fit.status.find("every one of the"), std::string::npos) << fit.status;
  for (const auto& p : fit.parameters) {
    EXPECT_FALSE(p.identifiable);
    EXPECT_DOUBLE_EQ(p.value, p.initial);
  }
}

TEST(HonestCalibration, TheFittedModelMustReachTheEndOfTheData) {
  vc::FitProblem pb = linear_problem([](double v) { return 2.0 * (v - 50) / 100 + 1.0; });
  // The fit compares 50-350 ml; the whole data go on, and the fitted model stops at 300 ml.
  pb.final_model = [](const std::vector<double>& p) {
    return filling_run(linear_law, p, 400, 300);
  };
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_FALSE(fit.fitted);
  EXPECT_NE(fit.status.find("does not reach the end of the data"), std::string::npos) << fit.status;
}

TEST(TwoStageFit, TheModelsOptimumDespiteABiasedSurrogate) {
  // The surrogate is the model with an offset and a 10 % stiffer slope; output space mapping
  // must still land on the model's optimum (a = 2, b = 1.5), not the surrogate's.
  vc::FitProblem pb = linear_problem([](double v) { return 2.0 * (v - 50) / 100 + 1.5; });
  pb.surrogate = [](const std::vector<double>& p) {
    return filling_run([](const std::vector<double>& q,
                          double v) { return 1.1 * q[0] * (v - 50) / 100 + q[1] + 0.4; },
                       p, 350);
  };
  pb.budget.model_simulations = 20;
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_NEAR(fit.parameters[0].value, 2.0, 0.02);
  EXPECT_NEAR(fit.parameters[1].value, 1.5, 0.02);
  ASSERT_EQ(fit.stages.size(), 2u);
  EXPECT_GT(fit.stages[0].simulations, fit.stages[1].simulations);
}

TEST(TwoStageFit, TheModelRunsAFewTimesNotOncePerParameterAndIteration) {
  // Three parameters, the third one the data ignore; the model costs what the 3-D wall does,
  // so the mapping runs it once an iteration and the intervals come from the corrected
  // surrogate (no m + 1 model runs for a Jacobian).
  vc::FitProblem pb = linear_problem([](double v) { return 2.0 * (v - 50) / 100 + 1.5; });
  pb.parameters.push_back(parameter("c", 1.0));
  pb.surrogate = [](const std::vector<double>& p) {
    return filling_run([](const std::vector<double>& q,
                          double v) { return 1.1 * q[0] * (v - 50) / 100 + q[1] + 0.4; },
                       p, 350);
  };
  pb.budget.model_simulations = 40;
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_NEAR(fit.parameters[0].value, 2.0, 0.05);
  EXPECT_NEAR(fit.parameters[1].value, 1.5, 0.05);
  ASSERT_EQ(fit.stages.size(), 2u);
  EXPECT_LE(fit.stages[1].simulations, pb.budget.mapping_iterations + 1);
  EXPECT_FALSE(fit.parameters[2].identifiable);
  const bool said = std::any_of(fit.notes.begin(), fit.notes.end(), [](const std::string& n) {
    return n.find("corrected by the model's output") != std::string::npos;
  });
  EXPECT_TRUE(said);
}

TEST(HonestCalibration, AModelThatRunsNoneOfTheSurrogatesOptimaIsNotFittedAndSaysWhy) {
  // The surrogate runs everywhere; the model stops short everywhere (as the 3-D wall can
  // near the end of voiding): nothing is fitted on the model's behalf.
  vc::FitProblem pb = linear_problem([](double v) { return 3.0 * (v - 50) / 100; });
  pb.surrogate = pb.model;
  pb.model = [](const std::vector<double>& p) { return filling_run(linear_law, p, 350, 120); };
  pb.model_name = "wall";
  const auto fit = vc::fit_parameters(pb).result;
  EXPECT_FALSE(fit.fitted);
  EXPECT_NE(fit.status.find("wall ran none of the surrogate's best optima"), std::string::npos)
      << fit.status;
  ASSERT_EQ(fit.stages.size(), 2u);
  EXPECT_LE(fit.stages[1].simulations, 2);
  for (const auto& p : fit.parameters) EXPECT_FALSE(p.identifiable);
}
