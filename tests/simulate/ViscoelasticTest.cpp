// Step-stretch relaxation of the viscoelastic membrane (docs/physics.md §2.5, §6.6): after a
// sudden in-plane stretch held constant, the membrane stress relaxes as
// S∞ (1 + Σ β_α e^(-t/τ_α)), S∞ the plane-stress stress of the elastic neo-Hookean wall at
// the same stretch, and the thickness stays the elastic wall's.
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/simulate/materials/MaterialRegistry.h"
#include "wall/PlaneStress.h"

using namespace vesica::simulate;

namespace {

void expect_relaxation(const std::vector<std::pair<double, double>>& branches, double K) {
  MaterialSpec visco{"maxwell", {{"mu", 5e3}, {"K", K}}};
  for (std::size_t a = 0; a < branches.size(); ++a) {
    visco.params["beta" + std::to_string(a + 1)] = branches[a].first;
    visco.params["tau" + std::to_string(a + 1)] = branches[a].second;
  }
  const auto m = make_material(visco);
  const auto elastic = make_material({"neo-hookean", {{"mu", 5e3}, {"K", K}}});
  const double l = 1.4;
  Eigen::Matrix2d C2;
  C2 << l * l, 0.1, 0.1, 1.0 / l;
  const PlaneStressState held = plane_stress(*elastic, C2, MaterialPoint{}, 1.0, nullptr, nullptr);
  std::vector<double> h_old(m->history_size(), 0.0), h_new(h_old.size());
  MaterialPoint point;
  double t = 0.0;
  point.dt_s = 0.0;  // the step: instantaneous
  double worst = 0.0;
  for (int step = 0; step <= 200; ++step) {
    const PlaneStressState s = plane_stress(*m, C2, point, 1.0, h_old.data(), h_new.data());
    h_old = h_new;
    double factor = 1.0;
    for (const auto& [beta, tau] : branches) factor += beta * std::exp(-t / tau);
    const Eigen::Matrix2d expected = held.S * factor;
    worst = std::max(worst, (s.S - expected).norm() / expected.norm());
    EXPECT_NEAR(s.C33, held.C33, 1e-12 * held.C33);
    point.dt_s = 25.0 * (1 + step % 3);  // uneven steps
    t += point.dt_s;
  }
  std::cout << "[ relaxation ] worst relative deviation " << worst << std::endl;
  EXPECT_LT(worst, 1e-9);
}

}  // namespace

TEST(Viscoelastic, OneBranchRelaxation) {
  expect_relaxation({{0.15, 1000.0}}, 1e4);
}

TEST(Viscoelastic, ThreeBranchRelaxationOfANearlyIncompressibleWall) {
  expect_relaxation({{0.15, 1000.0}, {0.5, 100.0}, {1.0, 2000.0}}, 5e6);
}
