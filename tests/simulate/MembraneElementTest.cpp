// The membrane element and the pressure load: tangents against central finite
// differences; patch tests (uniform biaxial stretch → the analytic uniform stress, rigid
// rotation → zero stress).
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/simulate/materials/MaterialRegistry.h"
#include "wall/MembraneElement.h"
#include "wall/MembraneProblem.h"
#include "wall/PressureLoad.h"

using namespace vesica::simulate;

namespace {

std::array<Eigen::Vector3d, 3> reference_triangle() {
  return {Eigen::Vector3d(0.01, 0.002, 0.003), Eigen::Vector3d(0.031, 0.004, 0.0),
          Eigen::Vector3d(0.012, 0.027, 0.006)};
}

std::array<Eigen::Vector3d, 3> deformed(const std::array<Eigen::Vector3d, 3>& X) {
  Eigen::Matrix3d F;
  // Stretched in every in-plane direction: the element tangent is exact (consistent) for a
  // wall in tension; compressed walls get the tension-field geometric stiffness.
  F << 1.4, 0.1, 0.05, 0.05, 1.3, 0.1, 0.1, 0.05, 1.2;
  std::array<Eigen::Vector3d, 3> x;
  for (int a = 0; a < 3; ++a) x[a] = F * X[a] + Eigen::Vector3d(0.001, -0.002, 0.0005) * a;
  return x;
}

}  // namespace

TEST(MembraneElement, TangentMatchesFiniteDifferences) {
  for (const MaterialSpec& spec :
       {MaterialSpec{"neo-hookean", {{"mu", 5e3}, {"K", 1e4}}},
        MaterialSpec{"neo-hookean", {{"mu", 5e3}, {"K", 5e6}}},
        MaterialSpec{"fibers", {{"mu", 5e3}, {"K", 1e4}, {"k1", 300.0}, {"k2", 1.0}}}}) {
    const auto m = make_material(spec);
    const auto X = reference_triangle();
    const MembraneGeometry geo = membrane_geometry(X, 3e-3);
    const auto x = deformed(X);
    MaterialPoint point;
    const MembraneResponse r = membrane_response(geo, x, *m, point, 1.0, nullptr, nullptr);
    ASSERT_GT(r.stress.S.determinant(), 0.0) << "the check needs a wall in tension";
    ASSERT_GT(r.stress.S.trace(), 0.0);
    Matrix9 K_fd;
    for (int q = 0; q < 9; ++q) {
      const double h = 1e-7 * 0.03;
      auto xp = x, xm = x;
      xp[q / 3](q % 3) += h;
      xm[q / 3](q % 3) -= h;
      const auto rp = membrane_response(geo, xp, *m, point, r.stress.J2, nullptr, nullptr);
      const auto rm = membrane_response(geo, xm, *m, point, r.stress.J2, nullptr, nullptr);
      K_fd.col(q) = (rp.f_int - rm.f_int) / (2 * h);
    }
    EXPECT_LT((r.K - K_fd).norm() / r.K.norm(), 1e-6) << spec.name << " S =\n" << r.stress.S;
  }
}

TEST(PressureLoad, TangentMatchesFiniteDifferences) {
  HydrostaticPressure p{800.0, 1000.0, Eigen::Vector3d(0.0, 9.81, 0.0),
                        Eigen::Vector3d(0.0, 0.01, 0.0)};
  const auto x = deformed(reference_triangle());
  const HydrostaticPressure abdomen{150.0, 500.0, Eigen::Vector3d(0.0, 9.81, 0.0),
                                    Eigen::Vector3d(0.0, 0.02, 0.0)};
  const PressureResponse r = pressure_response(x, p, abdomen);
  Eigen::Matrix<double, 9, 9> fd;
  for (int q = 0; q < 9; ++q) {
    const double h = 1e-8;
    auto xp = x, xm = x;
    xp[q / 3](q % 3) += h;
    xm[q / 3](q % 3) -= h;
    fd.col(q) =
        (pressure_response(xp, p, abdomen).f - pressure_response(xm, p, abdomen).f) / (2 * h);
  }
  EXPECT_LT((r.dfdx - fd).norm() / r.dfdx.norm(), 1e-6);
  // Uniform pressure on a flat triangle: total force p·(area vector).
  HydrostaticPressure uniform{1000.0, 0.0, {}, {}};
  const auto ru = pressure_response(x, uniform, HydrostaticPressure{});
  const Eigen::Vector3d total = ru.f.segment<3>(0) + ru.f.segment<3>(3) + ru.f.segment<3>(6);
  const Eigen::Vector3d expected = 1000.0 * 0.5 * (x[1] - x[0]).cross(x[2] - x[0]);
  EXPECT_LT((total - expected).norm(), 1e-12 * expected.norm());
}

// A flat patch of triangles of very different shapes under uniform equibiaxial
// stretch λ: every element carries exactly the stress of the analytic plane-stress state,
// here for the (nearly) incompressible neo-Hookean membrane S_11 = μ (1 - λ⁻⁶)
// (Cauchy σ = μ(λ² - λ⁻⁴), S = σ/λ² with J = 1).
TEST(MembranePatch, UniformBiaxialStretchGivesUniformStress) {
  const double mu = 5e3, lambda = 1.3;
  const auto m = make_material({"neo-hookean", {{"mu", mu}, {"K", 1e4 * mu}}});
  const std::array<std::array<Eigen::Vector3d, 3>, 3> tris = {
      std::array<Eigen::Vector3d, 3>{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 0, 0),
                                     Eigen::Vector3d(0.2, 0.9, 0)},
      std::array<Eigen::Vector3d, 3>{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1.1, 1.3, 0),
                                     Eigen::Vector3d(0.2, 0.9, 0)},
      std::array<Eigen::Vector3d, 3>{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0.05, 0.01, 0),
                                     Eigen::Vector3d(0.02, 0.3, 0)}};
  const double S_expected = mu * (1.0 - std::pow(lambda, -6));
  for (const auto& X : tris) {
    const auto geo = membrane_geometry(X, 1e-3);
    std::array<Eigen::Vector3d, 3> x;
    for (int a = 0; a < 3; ++a) x[a] = lambda * X[a];
    const auto r = membrane_response(geo, x, *m, MaterialPoint{}, 1.0, nullptr, nullptr);
    EXPECT_NEAR(r.stress.S(0, 0), S_expected, 1e-3 * S_expected);
    EXPECT_NEAR(r.stress.S(1, 1), S_expected, 1e-3 * S_expected);
    EXPECT_NEAR(r.stress.S(0, 1), 0.0, 1e-9 * S_expected);
    EXPECT_NEAR(r.stress.C33, std::pow(lambda, -4), 1e-3);
  }
}

TEST(MembranePatch, RigidRotationGivesZeroStress) {
  const auto m = make_material({"fibers", {{"mu", 5e3}, {"K", 1e4}, {"k1", 1e4}, {"k2", 1.0}}});
  const auto X = reference_triangle();
  const auto geo = membrane_geometry(X, 3e-3);
  const Eigen::Matrix3d R =
      Eigen::AngleAxisd(0.9, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();
  std::array<Eigen::Vector3d, 3> x;
  for (int a = 0; a < 3; ++a) x[a] = R * X[a] + Eigen::Vector3d(0.3, -0.1, 0.2);
  const auto r = membrane_response(geo, x, *m, MaterialPoint{}, 1.0, nullptr, nullptr);
  EXPECT_LT(r.stress.S.norm(), 1e-9);
  EXPECT_LT(r.f_int.norm(), 1e-12);
  EXPECT_NEAR(r.stress.C33, 1.0, 1e-12);
}
