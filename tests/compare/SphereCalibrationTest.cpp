// Calibration against a known truth: a "measured" filling curve simulated on a spherical
// wall with mu = 3 kPa must give back mu = 3 kPa when the fit starts from 6 kPa, with a
// confidence interval that contains it and a near-zero residual — through the two stages
// (the coarse sphere surrogate, then the wall) and on the wall alone. And the calibration's
// names walked against the parameter catalogue for each named material.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/calibration/Calibration.h"
#include "vesica/simulate/ParameterCatalogue.h"
#include "vesica/simulate/protocol/Cystometry.h"
#include "vesica/simulate/wall/SphereMesh.h"

namespace vc = vesica::compare;
namespace vs = vesica::simulate;

namespace {

vc::CalibrationProblem sphere_problem() {
  vc::CalibrationProblem pb;
  vc::CystometryModel& m = pb.model;
  m.wall = vs::sphere_wall(0.02285, 3e-3, 6);  // 50 ml, 288 triangles
  vs::fix_sphere_rigid_modes(m.wall);
  m.protocol.start_ml = 50;
  m.protocol.capacity_ml = 200;
  m.protocol.gravity = false;
  m.protocol.void_after_fill = false;
  m.run.filling_only = true;
  // The truth computed as the calibration computes its curves: a fresh tangent every Newton
  // iteration (Calibration.cpp). Past its pressure peak this compressible wall (K/mu 3.3)
  // has neighbouring equilibria, and a curve from chord iterations lands 1.7 % away in mu.
  m.run.newton.reuse_tangent_ratio = 0.0;
  m.material = {"neo-hookean", {{"mu", 3e3}, {"K", 10e3}}};
  const auto truth = vs::run_cystometry(m.wall, m.material, m.protocol, m.run);
  EXPECT_TRUE(truth.completed) << truth.failure;
  pb.targets = vc::filling_targets(vc::analyse(vc::recording_from_history(truth.history)), 60, 200);
  m.material.params["mu"] = 6e3;
  vc::ModelParameter mu = vc::model_parameter("mu");
  mu.fit.initial = 6.0;
  pb.parameters = {mu};
  pb.budget.model_simulations = 30;
  return pb;
}

void expect_recovered(const vc::CalibrationResult& fit) {
  ASSERT_EQ(fit.parameters.size(), 1u);
  const auto& mu = fit.parameters[0];
  std::cout << "mu " << mu.value << " kPa [" << mu.ci_low << ", " << mu.ci_high << "], RMSE "
            << fit.rmse_cmh2o << " cmH2O, " << fit.simulations << " simulations, " << fit.seconds
            << " s, " << fit.status << "\n";
  EXPECT_NEAR(mu.value, 3.0, 0.03);
  EXPECT_LT(fit.rmse_cmh2o, 0.05);
  EXPECT_TRUE(mu.identifiable) << mu.note;
  EXPECT_LE(mu.ci_low, 3.0 + 1e-6);
  EXPECT_GE(mu.ci_high, 3.0 - 1e-6);
  EXPECT_TRUE(fit.fitted) << fit.status;
  EXPECT_EQ(fit.failed_simulations, 0);
  EXPECT_FALSE(fit.fitted_filling.x.empty());
}

}  // namespace

TEST(SphereCalibration, RecoversTheShearModulusOfASimulatedCurveThroughTheSurrogate) {
  const auto out = vc::calibrate(sphere_problem());
  expect_recovered(out.result);
  ASSERT_EQ(out.result.stages.size(), 2u);
  // The refinement needs a handful of wall runs, not a full search on the wall.
  EXPECT_LE(out.result.stages[1].simulations, 8);
}

TEST(SphereCalibration, RecoversTheShearModulusOfASimulatedCurveOnTheWallAlone) {
  vc::CalibrationProblem pb = sphere_problem();
  pb.use_surrogate = false;
  expect_recovered(vc::calibrate(pb).result);
}

// Issue 38: for each named material, every catalogue parameter a calibration fits is a
// calibration name with the catalogue's unit and search range, and a value set through that
// name (the geometric mean of its range, in its unit) is the value the model card shows in
// SI, the catalogue's factor applied once.
TEST(SphereCalibration, EachFittedNameSetsTheCatalogueValueOnTheCardForEachMaterial) {
  const vs::WallModel wall = vs::sphere_wall(0.02285, 3e-3, 6);
  std::size_t checked = 0;
  for (const vs::NamedMaterial& material : vs::named_materials()) {
    for (const vs::PhysicalParameter& p : vs::parameter_catalogue()) {
      if (!p.fitted() || !p.applies_to(material.name)) continue;
      SCOPED_TRACE(material.name + " " + p.name);
      const vc::ModelParameter c = vc::model_parameter(p.name);
      EXPECT_EQ(c.fit.unit, p.unit);
      EXPECT_EQ(c.fit.lower, p.fit_range->lower);
      EXPECT_EQ(c.fit.upper, p.fit_range->upper);
      const double value = std::sqrt(p.fit_range->lower * p.fit_range->upper);
      vs::MaterialSpec spec{material.name, {}};
      vs::ProtocolSettings protocol;
      c.apply(value, spec, protocol);
      const vs::ModelCard card = vs::planned_model_card(wall, spec, protocol, vs::RunOptions{});
      const std::vector<double> si = vs::card_value_si(card, p);
      ASSERT_FALSE(si.empty());
      EXPECT_NEAR(si.front(), value * p.si_per_unit, 1e-12 * value * p.si_per_unit);
      ++checked;
    }
  }
  // The urethra's and the drive's nine for every material, and the wall's where they apply.
  EXPECT_GT(checked, 5u * 9u);
}
