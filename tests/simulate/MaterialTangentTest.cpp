// Every registered material: D = 2 dS/dC against central finite differences of S(C),
// at a general (non-diagonal) C, with fibers in tension and the detrusor's active stress
// (isometric, shortening and lengthening: both branches of the Hill relation).
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/core/Error.h"

#include "vesica/simulate/materials/MaterialRegistry.h"

using namespace vesica::simulate;

namespace {

Eigen::Matrix3d general_C() {
  Eigen::Matrix3d F;
  F << 1.3, 0.2, 0.05, -0.1, 0.9, 0.15, 0.02, -0.07, 1.1;
  return F.transpose() * F;
}

Voigt6 finite_difference_tangent(const Material& m, const Eigen::Matrix3d& C,
                                 const MaterialPoint& point, const std::vector<double>& h_old) {
  std::vector<double> h_new(h_old.size());
  Voigt6 D_fd, D;
  for (int J = 0; J < 6; ++J) {
    const int k = kVoigtIndex[J][0], l = kVoigtIndex[J][1];
    const double h = 1e-6;
    Eigen::Matrix3d dC = Eigen::Matrix3d::Zero();
    dC(k, l) += h;
    if (k != l) dC(l, k) += h;
    Eigen::Matrix3d Sp, Sm;
    m.evaluate(C + dC, point, h_old.data(), h_new.data(), Sp, D);
    m.evaluate(C - dC, point, h_old.data(), h_new.data(), Sm, D);
    // dS_ij = 1/2 D_ijkl dC_kl summed over k, l
    D_fd.col(J) = to_voigt(Sp - Sm) / (2.0 * h) * (k == l ? 2.0 : 1.0);
  }
  return D_fd;
}

// The muscle's history (its last four doubles, DetrusorMuscle.h): each fiber's committed
// stretch is `rate_factor` times its stretch at C (> 1: the fiber shortens over the step)
// and its committed Hill factor 0.8.
void set_muscle_history(const Eigen::Matrix3d& C, const MaterialPoint& point, double rate_factor,
                        std::vector<double>& h) {
  for (int f = 0; f < 2; ++f) {
    const Eigen::Vector3d& a = point.fibers[f];
    h[h.size() - 4 + 2 * f] = rate_factor * std::sqrt(a.dot(C * a)) - 1.0;
    h[h.size() - 3 + 2 * f] = 0.8 - 1.0;
  }
}

void expect_consistent_tangent(const MaterialSpec& spec, double activation = 0.0,
                               double muscle_rate_factor = 0.0, double dt_s = 0.5) {
  const auto material = make_material(spec);
  MaterialPoint point;
  point.fibers = {Eigen::Vector3d(0.8, 0.6, 0.0), Eigen::Vector3d(-0.6, 0.8, 0.0)};
  point.dt_s = dt_s;
  point.activation = activation;
  std::vector<double> h_old(material->history_size());
  for (std::size_t i = 0; i < h_old.size(); ++i) h_old[i] = 100.0 * std::sin(double(i));
  const Eigen::Matrix3d C = general_C();
  if (muscle_rate_factor > 0.0) set_muscle_history(C, point, muscle_rate_factor, h_old);
  std::vector<double> h_new(h_old.size());
  Eigen::Matrix3d S;
  Voigt6 D;
  material->evaluate(C, point, h_old.data(), h_new.data(), S, D);
  const Voigt6 D_fd = finite_difference_tangent(*material, C, point, h_old);
  EXPECT_LT((D - D_fd).norm() / D.norm(), 1e-6) << spec.name << "\nD=\n" << D << "\nFD=\n" << D_fd;
  EXPECT_LT((D - D.transpose()).norm(), 1e-12 * D.norm()) << spec.name << ": not symmetric";
}

}  // namespace

TEST(MaterialTangent, NeoHookean) {
  expect_consistent_tangent({"neo-hookean", {{"mu", 5e3}, {"K", 1e4}}});
}

TEST(MaterialTangent, NeoHookeanNearlyIncompressible) {
  expect_consistent_tangent({"neo-hookean", {{"mu", 5e3}, {"K", 5e6}}});
}

TEST(MaterialTangent, MaxwellThreeBranches) {
  expect_consistent_tangent({"maxwell",
                             {{"mu", 5e3},
                              {"K", 1e4},
                              {"beta1", 0.15},
                              {"tau1", 1.0},
                              {"beta2", 0.5},
                              {"tau2", 10.0},
                              {"beta3", 2.0},
                              {"tau3", 0.1}}});
}

TEST(MaterialTangent, FibersViscoelasticInTension) {
  // General C stretches both fiber directions (Ī4 > 1 for the first at least).
  expect_consistent_tangent(
      {"fibers",
       {{"mu", 5e3}, {"K", 1e4}, {"k1", 1e4}, {"k2", 1.0}, {"beta", 0.15}, {"tau", 1.0}}});
}

TEST(MaterialTangent, ContractingDetrusorIsometricShorteningAndLengthening) {
  const MaterialSpec muscle{"fibers",
                            {{"mu", 5e3},
                             {"K", 1e4},
                             {"k1", 1e4},
                             {"k2", 1.0},
                             {"tone", 2e3},
                             {"contractility", 1e5},
                             {"optimal_stretch", 1.4},
                             {"stretch_width", 0.6}}};
  expect_consistent_tangent(muscle, 0.7, 1.0, 0.0);   // no time: the committed Hill factor
  expect_consistent_tangent(muscle, 0.7, 1.05, 0.5);  // shortening: concentric Hill branch
  expect_consistent_tangent(muscle, 0.7, 0.97, 0.5);  // lengthening: eccentric branch
}

TEST(MaterialTangent, DefaultBladderAndNeobladderWalls) {
  expect_consistent_tangent({"bladder", {}}, 0.6, 1.02);
  expect_consistent_tangent({"neobladder", {}}, 0.0, 0.0);
}

TEST(MaterialRegistry, RejectsUnknownNamesAndParameters) {
  EXPECT_THROW(make_material({"rubber", {}}), vesica::Error);
  EXPECT_THROW(make_material({"neo-hookean", {{"mu_kpa", 5.0}}}), vesica::Error);
  EXPECT_THROW(make_material({"neo-hookean", {{"mu", -1.0}}}), vesica::Error);
}

TEST(MaterialStress, ReferenceStateIsStressFree) {
  // At rest (activation 0, no tone), every law: the detrusor's default tone is 0 too.
  for (const std::string& name : material_names()) {
    const auto m = make_material({name, {}});
    std::vector<double> h(m->history_size(), 0.0), hn(h.size());
    Eigen::Matrix3d S;
    Voigt6 D;
    m->evaluate(Eigen::Matrix3d::Identity(), MaterialPoint{}, h.data(), hn.data(), S, D);
    EXPECT_LT(S.norm(), 1e-9) << name;
  }
}

// FEBio's volumetric law K/2 (ln J)² (beta_vol = 0) and the Ogden term at small β
// (docs/physics.md §2.3), at K/μ = 2 and 500.
TEST(MaterialTangent, LogSquaredVolumetricLaw) {
  for (double K : {1e4, 2.5e6})
    expect_consistent_tangent({"neo-hookean", {{"mu", 5e3}, {"K", K}, {"beta_vol", 0.0}}});
}

TEST(MaterialTangent, SmallBetaOgdenVolumetricTerm) {
  for (double beta : {1e-3, 1e-4})
    expect_consistent_tangent({"neo-hookean", {{"mu", 5e3}, {"K", 1e4}, {"beta_vol", beta}}});
}
