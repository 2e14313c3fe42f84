// Model-against-measurement metrics on curves with known differences.
#include <cmath>

#include <gtest/gtest.h>

#include "vesica/compare/analysis/ModelComparison.h"
#include "vesica/compare/analysis/PiecewiseLinear.h"

namespace vc = vesica::compare;

TEST(PiecewiseLinear, InterpolatesSortsAndAveragesDuplicates) {
  const vc::PiecewiseLinear f({2, 0, 1, 1}, {4, 0, 1, 3});
  EXPECT_DOUBLE_EQ(f(0.5), 1.0);  // between (0,0) and (1,2)
  EXPECT_DOUBLE_EQ(f(1.0), 2.0);  // mean of 1 and 3
  EXPECT_DOUBLE_EQ(f(-1), 0.0);
  EXPECT_DOUBLE_EQ(f(9), 4.0);
  const auto g = vc::grid(0, 10, 4);
  ASSERT_EQ(g.size(), 4u);
  EXPECT_DOUBLE_EQ(g.back(), 10);
}

TEST(ModelComparison, ConstantOffsetGivesThatRmseOverTheOverlap) {
  vc::Curve measured, simulated;
  for (double v = 25; v <= 350; v += 25) measured.x.push_back(v), measured.y.push_back(0.03 * v);
  for (double v = 50; v <= 400; v += 1)
    simulated.x.push_back(v), simulated.y.push_back(0.03 * v + 1.5);
  const auto d = vc::compare_filling(measured, simulated, {});
  EXPECT_DOUBLE_EQ(d.lo, 50);
  EXPECT_DOUBLE_EQ(d.hi, 350);
  EXPECT_NEAR(*d.rmse, 1.5, 1e-12);
  EXPECT_NEAR(*d.max_abs_error, 1.5, 1e-12);
  vc::ComparisonOptions o;
  o.volume_range_ml = {100, 200};
  const auto r = vc::compare_filling(measured, simulated, o);
  EXPECT_DOUBLE_EQ(r.lo, 100);
  EXPECT_DOUBLE_EQ(r.hi, 200);
  EXPECT_EQ(r.grid.size(), 21u);
}

TEST(ModelComparison, RmseOfALinearErrorIsItsRootMeanSquare) {
  // error e(V) = (V - 100)/50 on [100, 200] with 1 ml steps: RMSE -> sqrt(4/3)
  vc::Curve m{{100, 200}, {0, 0}}, s{{100, 200}, {0, 2}};
  const auto d = vc::compare_curves(m, s, -1e9, 1e9, 1.0);
  double sum = 0;
  for (int i = 0; i <= 100; ++i) sum += std::pow(i / 50.0, 2);
  EXPECT_NEAR(*d.rmse, std::sqrt(sum / 101), 1e-12);
  EXPECT_NEAR(*d.max_abs_error, 2.0, 1e-12);
}

TEST(ModelComparison, DisjointCurvesHaveNoMetric) {
  vc::Curve m{{0, 10}, {0, 1}}, s{{20, 30}, {0, 1}};
  EXPECT_FALSE(vc::compare_curves(m, s, -1e9, 1e9, 1.0).rmse);
}
