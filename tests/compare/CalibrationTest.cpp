// Calibration acceptance: the shear modulus of the level-1 model on the real bladder
// geometry (the CT reference label of ../shared -> closed surface of ~1,200 triangles ->
// wall) fitted to the shared recording's filling curve over 50-350 ml through
// vesica-compare --calibrate mu (simulations in process).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "CompareTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

TEST(Calibration, ShearModulusOnTheRealBladderFitsTheFillingCurve) {
  VESICA_REQUIRE_SHARED(label, "data/ct/abdomen-3mm/bladder-reference.nii.gz");
  const fs::path dir = scratch_dir("compare-calibration");
  // ~1,200 triangles: the filling curve is mesh-converged there (Pdet at 350 ml within
  // 0.3 % of a 2,474-triangle wall) and each of the ~10 simulations takes seconds.
  const long triangles = write_label_surface(label, dir / "wall.vtp", 1200);
  EXPECT_NEAR(triangles, 1200, 200);
  const auto r =
      run_command(compare_exe() + " --measured " + compare_data("normal-female-34y.csv").string() +
                  " --mesh " + (dir / "wall.vtp").string() +
                  " --calibrate mu --fit-volume-ml 50,350 -o " + (dir / "report").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = nlohmann::json::parse(read_text(dir / "report" / "metrics.json"));
  const auto& c = m["calibration"];
  const double mu = c["parameters"][0]["value"].get<double>();
  const double rmse = c["rmse_cmh2o"].get<double>();
  std::cout << "fitted mu " << mu << " kPa, RMSE " << rmse << " cmH2O, " << c["simulations"]
            << " simulations, " << c["seconds"] << " s\n";
  EXPECT_LE(rmse, 2.0);
  EXPECT_GE(mu, 1.0);
  EXPECT_LE(mu, 10.0);
  EXPECT_LE(c["parameters"][0]["ci95_low"].get<double>(), mu);
  EXPECT_GE(c["parameters"][0]["ci95_high"].get<double>(), mu);
  EXPECT_DOUBLE_EQ(c["volume_range_ml"][0].get<double>(), 50);
  EXPECT_DOUBLE_EQ(c["volume_range_ml"][1].get<double>(), 349);
}
