// Issue 7 acceptance on the real CT bladder of ../shared: the reference label becomes a
// closed wall surface (vesica-surface, ~1,200 triangles, outlet at the bladder neck), and
// vesica-simulate runs a full cystometry on it: 50 -> 350 ml at 50 ml/min, then voiding
// by abdominal straining (--drive straining: a neobladder's way, or a detrusor that cannot)
// through the urethra law, labelled so in the summary and history.csv. Checked against bookkeeping
// truths that do not come from the solver: V(t) = V0 + infused - voided at every row, the
// protocol's volumes and rate, PVR = capacity - voided, and the ICS indices from their definitions.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "HistoryCsv.h"
#include "ShellCommand.h"
#include "TestData.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

int run(const std::string& command, std::string& output) {
  CommandResult r = run_command(command);
  output += r.output;
  return r.exit_code;
}

}  // namespace

TEST(PatientCystometry, RealCtBladderFillsTo350MlAndVoids) {
  VESICA_REQUIRE_SHARED(label, "data/ct/abdomen-3mm/bladder-reference.nii.gz");
  const fs::path dir = scratch_dir("simulate-patient");
  std::string out;
  ASSERT_EQ(run((bin_dir() / "vesica-surface").string() + " " + label.string() + " -o " +
                    (dir / "bladder.vtp").string() + " --target-triangles 1200 --outlet auto",
                out),
            0)
      << out;
  ASSERT_EQ(run((bin_dir() / "vesica-simulate").string() + " " + (dir / "bladder.vtp").string() +
                    " -o " + (dir / "sim").string() +
                    " --mu-kpa 3 --drive straining --straining-kpa 4 --no-series --json",
                out),
            0)
      << out;
  const auto summary = nlohmann::json::parse(std::ifstream(dir / "sim" / "summary.json"));
  const auto rows = read_history(dir / "sim" / "history.csv");
  ASSERT_GT(rows.size(), 10u);
  std::cout << "[ patient ] " << summary["triangles"] << " triangles, Pdet at capacity "
            << summary["pdet_at_capacity_cmh2o"] << " cmH2O, Qmax " << summary["qmax_ml_s"]
            << " ml/s, voided " << summary["voided_ml"] << " ml, PVR " << summary["pvr_ml"]
            << " ml, " << summary["compute_s"] << " s, newton " << summary["newton"] << std::endl;
  EXPECT_TRUE(summary["completed"].get<bool>());
  EXPECT_NEAR(summary["triangles"].get<double>(), 1200, 300);
  // Protocol: starts at the 50 ml residual volume, fills at 50 ml/min to 350 ml.
  EXPECT_NEAR(rows.front().volume, 50.0, 1e-6);
  EXPECT_NEAR(summary["capacity_ml"].get<double>(), 350.0, 1e-3);
  double t_capacity = 0.0;
  for (const HistoryCsvRow& r : rows) {
    EXPECT_NEAR(r.volume, 50.0 + r.infused - r.voided, 1e-6 * r.volume) << "t = " << r.t;
    if (r.infused < 300.0 - 1e-9) {
      EXPECT_NEAR(r.infused, 50.0 / 60.0 * r.t, 1e-6 * (1 + r.t));
    }
    if (t_capacity == 0.0 && r.infused >= 300.0 - 1e-6) t_capacity = r.t;
  }
  EXPECT_NEAR(t_capacity, 360.0, 1e-3);  // 300 ml at 50 ml/min
  EXPECT_LT(summary["mass_balance_error_max_rel"].get<double>(), 1e-6);
  // Filling pressure: positive and finite; it is what the issue asks to report.
  EXPECT_GT(summary["pdet_at_capacity_cmh2o"].get<double>(), 0.0);
  // Voiding: flow, and the bookkeeping of the ICS indices.
  const double voided = summary["voided_ml"].get<double>();
  EXPECT_GT(voided, 100.0);
  EXPECT_NEAR(summary["pvr_ml"].get<double>(), 350.0 - voided, 1e-3);
  const double qmax = summary["qmax_ml_s"].get<double>();
  const double pdet_qmax = summary["pdet_at_qmax_cmh2o"].get<double>();
  EXPECT_GT(qmax, 1.0);
  EXPECT_NEAR(summary["booi"].get<double>(), pdet_qmax - 2 * qmax, 1e-9);
  EXPECT_NEAR(summary["bci"].get<double>(), pdet_qmax + 5 * qmax, 1e-9);
  // Straining voided it, and every output says so.
  EXPECT_EQ(summary["voiding_drive"], "straining");
  std::ifstream csv(dir / "sim" / "history.csv");
  std::string first;
  std::getline(csv, first);
  EXPECT_EQ(first, "# vesica-simulate cystometry, voided by abdominal straining");
}
