// The volumetric laws of docs/physics.md §2.3: FEBio's K/2 (ln J)² (beta_vol = 0) and the
// Ogden term at small β, whose stress must keep its digits (expm1 form). Their tangents are
// checked with every material's in MaterialTangentTest.cpp.
#include <gtest/gtest.h>

#include <cmath>

#include "vesica/core/Error.h"
#include "vesica/simulate/materials/MaterialRegistry.h"

using namespace vesica::simulate;

namespace {

Eigen::Matrix3d stress(const Material& m, const Eigen::Matrix3d& C) {
  Eigen::Matrix3d S;
  Voigt6 D;
  m.evaluate(C, MaterialPoint{}, nullptr, nullptr, S, D);
  return S;
}

}  // namespace

// A pure dilation C = J^(2/3) I has no isochoric stress, so S = (J dΨ/dJ) C⁻¹ with
// J dΨ/dJ = K ln J for (K/2)(ln J)² and (K/β)(1 - J^(-β)) for Ogden; the latter's series
// K ln J (1 - β ln J / 2 + β² ln² J / 6) is the truth at small β ln J, where the difference
// 1 - J^(-β) of the plain formula would have lost most digits.
TEST(VolumetricLaw, DilationStressKeepsItsDigitsAtSmallBeta) {
  const double K = 1e4;
  for (double J : {1.0 + 1e-7, 1.01, 1.3}) {
    const Eigen::Matrix3d C = std::pow(J, 2.0 / 3.0) * Eigen::Matrix3d::Identity();
    // ln J as the material sees it (from det C), and a negligible μ: the pure dilation's
    // isochoric stress is round-off of μ, not zero.
    const double L = std::log(std::sqrt(C.determinant()));
    const double log_law =
        stress(*make_material({"neo-hookean", {{"mu", 1e-9}, {"K", K}, {"beta_vol", 0.0}}}), C)(0,
                                                                                                0) *
        C(0, 0);
    EXPECT_NEAR(log_law, K * L, 1e-13 * K * L) << "J " << J;
    for (double beta : {1e-3, 1e-4}) {
      const double series = K * L * (1.0 - beta * L / 2.0 + beta * beta * L * L / 6.0);
      const double ogden =
          stress(*make_material({"neo-hookean", {{"mu", 1e-9}, {"K", K}, {"beta_vol", beta}}}), C)(
              0, 0) *
          C(0, 0);
      EXPECT_NEAR(ogden, series, 1e-12 * K * L) << "J " << J << " beta " << beta;
    }
  }
}

TEST(VolumetricLaw, NegativeBetaIsRejected) {
  EXPECT_THROW(make_material({"neo-hookean", {{"beta_vol", -1.0}}}), vesica::Error);
}
