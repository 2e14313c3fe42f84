// vesica-compare end to end: the acceptance numbers of the shared recording in
// metrics.json, model against a synthetic history, and bad input (one line naming file,
// row and column; exit 1; nothing written).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "CompareTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

TEST(CompareCli, MeasuredAndSimulatedGiveMetricsAndReport) {
  const fs::path out = scratch_dir("compare-cli") / "report";
  const auto r =
      run_command(compare_exe() + " --measured " + compare_data("normal-female-34y.csv").string() +
                  " --simulated " + compare_data("synthetic-history.csv").string() + " -o " +
                  out.string() + " --report " + (out.parent_path() / "s.json").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto m = nlohmann::json::parse(read_text(out / "metrics.json"));
  const auto& p = m["measured"]["parameters"];
  EXPECT_DOUBLE_EQ(p["capacity_ml"].get<double>(), 349);
  EXPECT_DOUBLE_EQ(p["qmax_ml_s"].get<double>(), 17);
  EXPECT_DOUBLE_EQ(p["pdet_qmax_cmh2o"].get<double>(), 5);
  EXPECT_DOUBLE_EQ(p["voided_ml"].get<double>(), 350);
  EXPECT_DOUBLE_EQ(p["pvr_ml"].get<double>(), 0);
  EXPECT_DOUBLE_EQ(p["booi"].get<double>(), -29);
  EXPECT_DOUBLE_EQ(p["bci"].get<double>(), 90);
  // a woman (the recording's header): the male classes are not given (ReportContentTest)
  EXPECT_EQ(p["booi_class"], "");
  EXPECT_EQ(p["bci_class"], "");
  EXPECT_DOUBLE_EQ(p["compliance_ml_per_cmh2o"].get<double>(), 108);
  EXPECT_EQ(m["measured"]["artefacts"][0]["event"], "strong desire");
  EXPECT_EQ(m["measured"]["artefacts"][0]["kind"], "abdominal spike");
  EXPECT_EQ(m["measured"]["artefacts"][0]["line"], 20);
  // differences simulated - measured from the analytic synthetic values
  const auto& d = m["comparison"]["parameter_difference_simulated_minus_measured"];
  EXPECT_DOUBLE_EQ(d["qmax_ml_s"].get<double>(), 18 - 17);
  EXPECT_NEAR(d["compliance_ml_per_cmh2o"].get<double>(), 100 - 108, 1e-9);
  EXPECT_DOUBLE_EQ(d["capacity_ml"].get<double>(), 350 - 349);
  // the overlap of 25..349 ml (measured) and 50..350 ml (synthetic)
  EXPECT_DOUBLE_EQ(m["comparison"]["filling_pdet"]["range_lo"].get<double>(), 50);
  EXPECT_DOUBLE_EQ(m["comparison"]["filling_pdet"]["range_hi"].get<double>(), 349);
  EXPECT_GT(m["comparison"]["filling_pdet"]["rmse_cmh2o"].get<double>(), 0);
  EXPECT_TRUE(fs::exists(out / "index.html"));
  const auto s = nlohmann::json::parse(read_text(out.parent_path() / "s.json"));
  EXPECT_DOUBLE_EQ(s["capacity_ml"].get<double>(), 349);
}

TEST(CompareCli, MeasuredOnlyIsEnough) {
  const fs::path out = scratch_dir("compare-cli-measured") / "report";
  const auto r =
      run_command(compare_exe() + " --measured " + compare_data("normal-female-34y.csv").string() +
                  " -o " + out.string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto s = nlohmann::json::parse(r.output);
  EXPECT_DOUBLE_EQ(s["qmax_ml_s"].get<double>(), 17);
  EXPECT_TRUE(nlohmann::json::parse(read_text(out / "metrics.json"))["simulated"].is_null());
}

TEST(CompareCli, BadInputIsOneLineAndWritesNothing) {
  const fs::path dir = scratch_dir("compare-cli-bad");
  const fs::path csv = dir / "bad.csv";
  std::ofstream(csv) << "time,pves_cmh2o,pabd_cmh2o,infused_ml\n00:01,1,0,0\n00:02,?,1,1\n";
  const auto r = run_command(compare_exe() + " --measured " + csv.string() + " -o " +
                             (dir / "report").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  EXPECT_NE(r.output.find(csv.string() + ": row 3, column \"pves_cmh2o\""), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(dir / "report"));
  const auto usage = run_command(compare_exe() + " -o " + (dir / "report").string());
  EXPECT_EQ(usage.exit_code, 2) << usage.output;
}
