// The tension-field (wrinkling) membrane against independent truths: a sheet pulled along
// one direction and squeezed across it beyond its natural width carries exactly the
// uniaxial stress of that pull (found here by a 1-D root solve of the plain plane-stress
// law, and by the incompressible closed form), whatever the squeeze; a sheet shortened in
// every direction carries nothing; and the tangent matches central differences. Its
// regularised form keeps a share of the plain law where the sheet wrinkles.
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/simulate/materials/MaterialRegistry.h"
#include "wall/MembraneElement.h"
#include "wall/TensionField.h"

using namespace vesica::simulate;

namespace {

Eigen::Matrix2d rotation(double phi) {
  return Eigen::Rotation2Dd(phi).toRotationMatrix();
}

// C of a stretch λ1 along angle φ and λ2 across it.
Eigen::Matrix2d stretched(double l1, double l2, double phi) {
  const Eigen::Matrix2d R = rotation(phi);
  return R * Eigen::Vector2d(l1 * l1, l2 * l2).asDiagonal() * R.transpose();
}

// Uniaxial plane stress S11 at stretch λ1 with S22 = 0: bisection on the width ν.
double uniaxial_S11(const Material& m, double l1) {
  double lo = 0.1, hi = 1.5;
  for (int it = 0; it < 200; ++it) {
    const double nu = 0.5 * (lo + hi);
    const auto s = plane_stress(m, stretched(l1, nu, 0.0), MaterialPoint{}, 1.0, nullptr, nullptr);
    (s.S(1, 1) > 0.0 ? hi : lo) = nu;
  }
  const double nu = 0.5 * (lo + hi);
  return plane_stress(m, stretched(l1, nu, 0.0), MaterialPoint{}, 1.0, nullptr, nullptr).S(0, 0);
}

PlaneStressState relaxed(const Material& m, const Eigen::Matrix2d& C) {
  return tension_field_stress(m, C, MaterialPoint{}, 1.0, nullptr, nullptr);
}

// The change of C for a strain step h in Voigt component j (E11, E22, 2 E12).
Eigen::Matrix2d strain_step(int j, double h) {
  Eigen::Matrix2d dC = Eigen::Matrix2d::Zero();
  if (j < 2)
    dC(j, j) = 2.0 * h;  // dE_jj = h
  else
    dC(0, 1) = dC(1, 0) = h;  // 2 dE12 = h
  return dC;
}

// dS/dE (Voigt) of the in-plane stress S(C) by central differences at C0.
template <class StressAt>
Eigen::Matrix3d central_difference_tangent(const StressAt& stress_at, const Eigen::Matrix2d& C0,
                                           double h) {
  Eigen::Matrix3d fd;
  for (int j = 0; j < 3; ++j) {
    const Eigen::Matrix2d dC = strain_step(j, h);
    const Eigen::Matrix2d dS = (stress_at(C0 + dC) - stress_at(C0 - dC)) / (2.0 * h);
    fd.col(j) << dS(0, 0), dS(1, 1), dS(0, 1);
  }
  return fd;
}

}  // namespace

TEST(TensionField, TautSheetKeepsThePlaneStressLaw) {
  const auto m = make_material({"neo-hookean", {{"mu", 5e3}, {"K", 5e6}}});
  const Eigen::Matrix2d C = stretched(1.3, 1.1, 0.4);
  const auto plain = plane_stress(*m, C, MaterialPoint{}, 1.0, nullptr, nullptr);
  const auto tf = relaxed(*m, C);
  EXPECT_EQ(tf.wrinkling, Wrinkling::taut);
  EXPECT_LT((tf.S - plain.S).norm(), 1e-12 * plain.S.norm());
  EXPECT_LT((tf.D - plain.D).norm(), 1e-12 * plain.D.norm());
}

TEST(TensionField, WrinkledSheetCarriesTheUniaxialStressOfItsPull) {
  const double mu = 5e3;
  const auto m = make_material({"neo-hookean", {{"mu", mu}, {"K", 1e3 * mu}}});
  for (double l1 : {1.05, 1.3, 1.8}) {
    const double S11 = uniaxial_S11(*m, l1);
    // Incompressible neo-Hookean strip: Cauchy σ = μ (λ² - 1/λ), S = σ / λ².
    EXPECT_NEAR(S11, mu * (1.0 - std::pow(l1, -3)), 2e-3 * S11);
    // Below the natural width ≈ λ1^(-1/2) of the pulled strip.
    for (double l2 : {0.3, 0.6, 0.95 / std::sqrt(l1)})
      for (double phi : {0.0, 0.7, -2.0}) {
        const auto s = relaxed(*m, stretched(l1, l2, phi));
        ASSERT_EQ(s.wrinkling, Wrinkling::wrinkled) << l1 << " " << l2;
        const Eigen::Vector2d along = rotation(phi).col(0), across = rotation(phi).col(1);
        // S* = S11 a aᵀ in the reference frame (the pull direction a is the tension one).
        EXPECT_NEAR(along.dot(s.S * along), S11, 1e-8 * S11) << l1 << " " << l2 << " " << phi;
        EXPECT_NEAR(across.dot(s.S * across), 0.0, 1e-8 * S11);
        EXPECT_NEAR(along.dot(s.S * across), 0.0, 1e-8 * S11);
      }
  }
}

// Neo-Hookean takes the isotropic shortcut (no wrinkle solve); the fiber law, whose fibers
// are slack below stretch 1 too, goes through the wrinkle solve and must agree.
TEST(TensionField, SheetShortenedEverywhereIsSlack) {
  for (const MaterialSpec& spec :
       {MaterialSpec{"neo-hookean", {{"mu", 5e3}, {"K", 5e6}}},
        MaterialSpec{"fibers", {{"mu", 5e3}, {"K", 5e6}, {"k1", 2e3}, {"k2", 1.0}}}}) {
    const auto m = make_material(spec);
    for (const Eigen::Matrix2d& C :
         {stretched(0.8, 0.9, 0.3), stretched(0.5, 0.5, 0.0), stretched(0.99, 0.2, 1.0)}) {
      const auto s = relaxed(*m, C);
      EXPECT_EQ(s.wrinkling, Wrinkling::slack) << spec.name;
      EXPECT_EQ(s.S.norm(), 0.0);
      EXPECT_EQ(s.D.norm(), 0.0);
    }
  }
}

// 𝔻* = 2 dS*/dC: central differences of S* over C (E11, E22, 2 E12 perturbed in turn).
TEST(TensionField, WrinkledTangentMatchesFiniteDifferences) {
  for (const MaterialSpec& spec :
       {MaterialSpec{"neo-hookean", {{"mu", 5e3}, {"K", 5e6}}},
        MaterialSpec{"fibers", {{"mu", 5e3}, {"K", 5e6}, {"k1", 2e3}, {"k2", 1.0}}}}) {
    const auto m = make_material(spec);
    for (const Eigen::Matrix2d& C0 : {stretched(1.3, 0.7, 0.5), stretched(1.1, 0.5, -1.2)}) {
      const auto s = relaxed(*m, C0);
      ASSERT_EQ(s.wrinkling, Wrinkling::wrinkled) << spec.name;
      const Eigen::Matrix3d fd = central_difference_tangent(
          [&](const Eigen::Matrix2d& C) { return relaxed(*m, C).S; }, C0, 1e-6);
      EXPECT_LT((fd - s.D).norm(), 1e-5 * s.D.norm()) << spec.name << "\n" << fd << "\n\n" << s.D;
    }
  }
}

// The regularised tension field (physics.md §1.6) by its definition, from the two laws
// above: a taut sheet is the plain law's; a slack one carries exactly ε of the plain law's
// compression (the relaxed stress being zero); a wrinkled one ε of the plain stress plus
// 1 − ε of the uniaxial pull; and its tangent is the derivative of its stress.
TEST(TensionField, ARegularisedWallKeepsItsShareOfThePlainLaw) {
  const double mu = 5e3, eps = 0.1;
  const auto m = make_material({"neo-hookean", {{"mu", mu}, {"K", 1e3 * mu}}});
  const auto regularised = [&](const Eigen::Matrix2d& C) {
    return regularised_tension_field_stress(*m, C, MaterialPoint{}, 1.0, nullptr, nullptr, eps);
  };
  const auto plain = [&](const Eigen::Matrix2d& C) {
    return plane_stress(*m, C, MaterialPoint{}, 1.0, nullptr, nullptr);
  };
  const Eigen::Matrix2d taut = stretched(1.3, 1.1, 0.4);
  EXPECT_LT((regularised(taut).S - plain(taut).S).norm(), 1e-12 * plain(taut).S.norm());

  const Eigen::Matrix2d slack = stretched(0.8, 0.9, 0.3);
  const PlaneStressState s = regularised(slack);
  EXPECT_EQ(s.wrinkling, Wrinkling::slack);
  EXPECT_LT((s.S - eps * plain(slack).S).norm(), 1e-12 * plain(slack).S.norm());
  EXPECT_LT(s.S.eigenvalues().real().maxCoeff(), 0.0);  // compression, a tenth of the plain law's

  const double l1 = 1.3, S11 = uniaxial_S11(*m, l1);
  const Eigen::Matrix2d wrinkled = stretched(l1, 0.6, 0.0);
  const PlaneStressState w = regularised(wrinkled);
  ASSERT_EQ(w.wrinkling, Wrinkling::wrinkled);
  const Eigen::Matrix2d expected =
      (1.0 - eps) * Eigen::Vector2d(S11, 0.0).asDiagonal().toDenseMatrix() +
      eps * plain(wrinkled).S;
  EXPECT_LT((w.S - expected).norm(), 1e-6 * S11);

  for (const Eigen::Matrix2d& C0 : {slack, wrinkled}) {
    const Eigen::Matrix3d D = regularised(C0).D;
    const Eigen::Matrix3d fd = central_difference_tangent(
        [&](const Eigen::Matrix2d& C) { return regularised(C).S; }, C0, 1e-6);
    EXPECT_LT((fd - D).norm(), 1e-5 * D.norm()) << fd << "\n\n" << D;
  }
}

// Random states across taut, wrinkled and slack: the tangent is the derivative of the
// stress wherever the state does not change within the difference step.
TEST(TensionField, TangentMatchesFiniteDifferencesAcrossStates) {
  const auto m = make_material({"neo-hookean", {{"mu", 3e3}, {"K", 3e6}}});
  std::srand(7);
  auto uniform = [](double a, double b) { return a + (b - a) * std::rand() / double(RAND_MAX); };
  int wrinkled = 0;
  for (int k = 0; k < 300; ++k) {
    const Eigen::Matrix2d C0 = stretched(uniform(0.3, 1.6), uniform(0.2, 1.3), uniform(-3.0, 3.0));
    const auto s = relaxed(*m, C0);
    Eigen::Matrix3d fd;
    const double h = 1e-7;
    bool same_state = true;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Matrix2d dC = strain_step(j, h);
      const auto sp = relaxed(*m, C0 + dC), sm = relaxed(*m, C0 - dC);
      same_state = same_state && sp.wrinkling == s.wrinkling && sm.wrinkling == s.wrinkling;
      const Eigen::Matrix2d dS = (sp.S - sm.S) / (2.0 * h);
      fd.col(j) << dS(0, 0), dS(1, 1), dS(0, 1);
    }
    if (!same_state) continue;
    wrinkled += s.wrinkling == Wrinkling::wrinkled;
    EXPECT_LE((fd - s.D).norm(), 1e-4 * std::max(s.D.norm(), 1.0))
        << "state " << int(s.wrinkling) << "\n"
        << C0 << "\n"
        << fd << "\n\n"
        << s.D;
  }
  EXPECT_GT(wrinkled, 50);
}

// The element with the wrinkling membrane: its stiffness (material with 𝔻*, geometric
// with S*) is the derivative of its nodal forces, in taut, wrinkled and slack states.
TEST(TensionField, ElementTangentMatchesFiniteDifferences) {
  const auto m = make_material({"neo-hookean", {{"mu", 3e3}, {"K", 3e6}}});
  const std::array<Eigen::Vector3d, 3> X = {Eigen::Vector3d(0.0, 0.0, 0.0),
                                            Eigen::Vector3d(0.002, 0.0, 0.0),
                                            Eigen::Vector3d(0.0007, 0.0017, 0.0)};
  const MembraneGeometry geo = membrane_geometry(X, 3e-3);
  std::srand(11);
  auto uniform = [](double a, double b) { return a + (b - a) * std::rand() / double(RAND_MAX); };
  int counted[3] = {0, 0, 0};
  for (int k = 0; k < 300; ++k) {
    Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F(i, j) = (i == j ? uniform(0.4, 1.4) : uniform(-0.4, 0.4));
    std::array<Eigen::Vector3d, 3> x;
    for (int a = 0; a < 3; ++a) x[a] = F * X[a];
    MembraneResponse r;
    try {
      r = membrane_response(geo, x, *m, MaterialPoint{}, 1.0, nullptr, nullptr, true);
    } catch (const std::runtime_error&) {
      continue;  // inverted
    }
    Matrix9 fd;
    bool same_state = true;
    const double h = 1e-10;
    for (int j = 0; j < 9; ++j) {
      auto xp = x, xm = x;
      xp[j / 3](j % 3) += h;
      xm[j / 3](j % 3) -= h;
      const auto rp = membrane_response(geo, xp, *m, MaterialPoint{}, 1.0, nullptr, nullptr, true);
      const auto rm = membrane_response(geo, xm, *m, MaterialPoint{}, 1.0, nullptr, nullptr, true);
      same_state = same_state && rp.stress.wrinkling == r.stress.wrinkling &&
                   rm.stress.wrinkling == r.stress.wrinkling;
      fd.col(j) = (rp.f_int - rm.f_int) / (2.0 * h);
    }
    if (!same_state) continue;
    ++counted[int(r.stress.wrinkling)];
    EXPECT_LE((fd - r.K).norm(), 1e-5 * std::max(r.K.norm(), 1e-3))
        << "state " << int(r.stress.wrinkling) << " |K| " << r.K.norm();
  }
  EXPECT_GT(counted[1], 30);
  EXPECT_GT(counted[2], 10);
}

// The viscous default wall, contracting: the membrane tangent (elastic, branch and muscle)
// is the derivative of the membrane stress, taut and wrinkled, and it is symmetric — the
// wall keeps the symmetric LDLᵀ solver.
TEST(TensionField, ViscousMembraneTangentIsConsistentAndSymmetric) {
  const auto m = make_material({"bladder", {{"contractility", 20e3}}});
  MaterialPoint point;
  point.dt_s = 0.5;
  point.activation = 0.6;
  point.fibers = {Eigen::Vector3d(0.8, 0.6, 0.0), Eigen::Vector3d(-0.6, 0.8, 0.0)};
  std::vector<double> h_old(m->history_size()), h_new(h_old.size());
  for (std::size_t i = 0; i < h_old.size(); ++i) h_old[i] = 30.0 * std::sin(double(i));
  h_old[h_old.size() - 4] = h_old[h_old.size() - 2] = 0.4;   // fibers' committed stretch - 1
  h_old[h_old.size() - 3] = h_old[h_old.size() - 1] = -0.2;  // Hill factor - 1
  int wrinkled = 0;
  for (const Eigen::Matrix2d& C0 : {stretched(1.5, 1.3, 0.4), stretched(1.4, 0.6, -0.9)}) {
    auto at = [&](const Eigen::Matrix2d& C) {
      return tension_field_stress(*m, C, point, 1.0, h_old.data(), h_new.data());
    };
    const auto s = at(C0);
    wrinkled += s.wrinkling == Wrinkling::wrinkled;
    const Eigen::Matrix3d fd =
        central_difference_tangent([&](const Eigen::Matrix2d& C) { return at(C).S; }, C0, 1e-7);
    EXPECT_LT((fd - s.D).norm(), 1e-5 * s.D.norm()) << int(s.wrinkling) << "\n"
                                                    << fd << "\n\n"
                                                    << s.D;
    EXPECT_LT((s.D - s.D.transpose()).norm(), 1e-12 * s.D.norm()) << int(s.wrinkling);
  }
  EXPECT_EQ(wrinkled, 1);
}
