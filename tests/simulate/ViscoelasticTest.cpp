// Step-stretch relaxation (docs/physics.md §2): after a sudden stretch held constant, the
// non-volumetric stress relaxes as S∞ (1 + Σ β_α e^(-t/τ_α)); S∞ and S_vol come from the
// elastic neo-Hookean material at the same C.
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/simulate/MaterialRegistry.h"

using namespace vesica::simulate;

namespace {

void expect_relaxation(const std::vector<std::pair<double, double>>& branches) {
  MaterialSpec visco{"maxwell", {{"mu", 5e3}, {"K", 1e4}}};
  for (std::size_t a = 0; a < branches.size(); ++a) {
    visco.params["beta" + std::to_string(a + 1)] = branches[a].first;
    visco.params["tau" + std::to_string(a + 1)] = branches[a].second;
  }
  const auto m = make_material(visco);
  const auto elastic = make_material({"neo-hookean", {{"mu", 5e3}, {"K", 1e4}}});
  const auto S_inf_only = make_material({"neo-hookean", {{"mu", 5e3}, {"K", 1e-30}}});
  const double l = 1.4;
  const Eigen::Matrix3d C = Eigen::Vector3d(l * l, 1.0 / l, 1.1).asDiagonal();
  Eigen::Matrix3d S, S_el, S_inf;
  Voigt6 D;
  elastic->evaluate(C, MaterialPoint{}, nullptr, nullptr, S_el, D);
  S_inf_only->evaluate(C, MaterialPoint{}, nullptr, nullptr, S_inf, D);
  const Eigen::Matrix3d S_vol = S_el - S_inf;
  std::vector<double> h_old(m->history_size(), 0.0), h_new(h_old.size());
  MaterialPoint point;
  double t = 0.0;
  point.dt_s = 0.0;  // the step: instantaneous
  double worst = 0.0;
  for (int step = 0; step <= 200; ++step) {
    m->evaluate(C, point, h_old.data(), h_new.data(), S, D);
    h_old = h_new;
    double factor = 1.0;
    for (const auto& [beta, tau] : branches) factor += beta * std::exp(-t / tau);
    const Eigen::Matrix3d expected = S_vol + S_inf * factor;
    worst = std::max(worst, std::abs((S - S_vol)(0, 0) / (expected - S_vol)(0, 0) - 1.0));
    point.dt_s = 25.0 * (1 + step % 3);  // uneven steps
    t += point.dt_s;
  }
  std::cout << "[ relaxation ] worst relative deviation " << worst << std::endl;
  EXPECT_LT(worst, 0.005);
}

}  // namespace

TEST(Viscoelastic, OneBranchRelaxation) {
  expect_relaxation({{0.15, 1000.0}});
}

TEST(Viscoelastic, ThreeBranchRelaxation) {
  expect_relaxation({{0.15, 1000.0}, {0.5, 100.0}, {1.0, 2000.0}});
}
