// Calibration against a known truth: a "measured" filling curve simulated on a spherical
// wall with mu = 3 kPa must give back mu = 3 kPa when the fit starts from 6 kPa, with a
// confidence interval that contains it and a near-zero residual.
#include <gtest/gtest.h>

#include "vesica/compare/Calibration.h"
#include "vesica/compare/RecordingAnalysis.h"
#include "vesica/simulate/SphereMesh.h"

namespace vc = vesica::compare;
namespace vs = vesica::simulate;

TEST(SphereCalibration, RecoversTheShearModulusOfASimulatedCurve) {
  vc::CalibrationProblem pb;
  pb.wall = vs::sphere_wall(0.02285, 3e-3, 6);  // 50 ml, 288 triangles
  vs::fix_sphere_rigid_modes(pb.wall);
  pb.protocol.start_ml = 50;
  pb.protocol.capacity_ml = 200;
  pb.protocol.gravity = false;
  pb.protocol.void_after_fill = false;
  pb.run.filling_only = true;
  // The truth computed as calibrate() computes its curves: a fresh tangent every Newton
  // iteration (Calibration.cpp). Past its pressure peak this compressible wall (K/mu 3.3)
  // has neighbouring equilibria, and a curve from chord iterations lands 1.7 % away in mu.
  pb.run.newton.reuse_tangent_ratio = 0.0;
  pb.material = {"neo-hookean", {{"mu", 3e3}, {"K", 10e3}}};
  const auto truth = vs::run_cystometry(pb.wall, pb.material, pb.protocol, pb.run);
  ASSERT_TRUE(truth.completed) << truth.failure;
  pb.measured_filling = vc::analyse(vc::recording_from_history(truth.history)).filling;

  pb.material.params["mu"] = 6e3;
  vc::ParameterSpec mu = vc::parameter_spec("mu");
  mu.initial = 6.0;
  pb.parameters = {mu};
  pb.volume_lo_ml = 60;
  pb.volume_hi_ml = 200;
  pb.max_simulations = 30;
  const auto fit = vc::calibrate(pb);
  ASSERT_EQ(fit.parameters.size(), 1u);
  std::cout << "mu " << fit.parameters[0].value << " kPa [" << fit.parameters[0].ci_low << ", "
            << fit.parameters[0].ci_high << "], RMSE " << fit.rmse_cmh2o << " cmH2O, "
            << fit.simulations << " simulations, " << fit.seconds << " s, " << fit.status << "\n";
  EXPECT_NEAR(fit.parameters[0].value, 3.0, 0.03);
  EXPECT_LT(fit.rmse_cmh2o, 0.05);
  EXPECT_LE(fit.parameters[0].ci_low, 3.0 + 1e-6);
  EXPECT_GE(fit.parameters[0].ci_high, 3.0 - 1e-6);
  EXPECT_FALSE(fit.fitted_filling.x.empty());
}
