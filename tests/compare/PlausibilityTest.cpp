// Recordings whose numbers cannot be what their columns say are refused or flagged by a
// named plausibility rule (docs/compare.md, "Plausibility rules"; issue 37). Each case is
// the shared normal recording with one known mistake made to it: its pressures written in
// Pa or kPa, its flow in ml/min, its voided volume negated or multiplied, its voided column
// dropped. The recording as measured passes every rule.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "CompareTestSupport.h"
#include "EditedRecording.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/io/RecordingReader.h"

namespace fs = std::filesystem;
namespace vc = vesica::compare;
using vesica::test::compare_data;

namespace {

vesica::io::Recording shared() {
  return vesica::io::read_recording(compare_data("normal-female-34y.csv"));
}

void scale(std::vector<double>& v, double factor) {
  for (double& x : v) x *= factor;
}

// The rule named in the refusal of `r`, or "" when it is accepted.
std::string refusing_rule(const vesica::io::Recording& r) {
  try {
    vc::analyse_checked(r);
    return "";
  } catch (const vesica::Error& e) {
    const std::string what = e.what();
    const auto at = what.find("plausibility rule ");
    return at == std::string::npos ? what : what.substr(at + 18, what.find(')', at) - at - 18);
  }
}

std::vector<std::string> warned_rules(const vesica::io::Recording& r) {
  std::vector<std::string> rules;
  for (const auto& w : vc::analyse_checked(r).warnings) rules.push_back(w.rule);
  return rules;
}

}  // namespace

TEST(Plausibility, TheRecordingAsMeasuredPassesEveryRule) {
  EXPECT_EQ(refusing_rule(shared()), "");
  EXPECT_TRUE(warned_rules(shared()).empty());
}

TEST(Plausibility, PressuresInPascalLabelledCmH2OAreRefused) {
  auto r = shared();
  const double pa_per_cmh2o = vesica::units::kPaPerCmH2O;  // 98.0665 Pa per cmH2O
  for (auto* p : {&r.pves_cmh2o, &r.pabd_cmh2o, &r.pdet_recorded_cmh2o}) scale(*p, pa_per_cmh2o);
  EXPECT_EQ(refusing_rule(r), "pressure-in-pa");
}

TEST(Plausibility, PressuresInKilopascalLabelledCmH2OAreRefused) {
  auto r = shared();
  const double kpa_per_cmh2o = 1e-3 * vesica::units::kPaPerCmH2O;
  for (auto* p : {&r.pves_cmh2o, &r.pabd_cmh2o, &r.pdet_recorded_cmh2o}) scale(*p, kpa_per_cmh2o);
  EXPECT_EQ(refusing_rule(r), "pressure-in-kpa");
}

TEST(Plausibility, AFillingTableInKilopascalGetsTheComplianceWarning) {
  // Pdet alone (no Pves to tell the abdomen's pressure): the compliance gives it away,
  // 324 ml over 3 cmH2O read as 0.29: 1101 ml/cmH2O.
  auto r = shared();
  r.pves_cmh2o.clear();
  r.pabd_cmh2o.clear();
  scale(r.pdet_recorded_cmh2o, 1e-3 * vesica::units::kPaPerCmH2O);
  const auto rules = warned_rules(r);
  EXPECT_NE(std::find(rules.begin(), rules.end(), "compliance"), rules.end());
}

TEST(Plausibility, FlowInMlPerMinuteLabelledMlPerSecondIsRefused) {
  auto r = shared();
  scale(r.flow_ml_s, 60.0);  // Qmax 17 ml/s read as 1020
  EXPECT_EQ(refusing_rule(r), "flow-in-ml-min");
}

TEST(Plausibility, ANegativeVoidedVolumeIsRefused) {
  auto r = shared();
  scale(r.voided_ml, -1.0);
  EXPECT_EQ(refusing_rule(r), "negative-volume");
}

TEST(Plausibility, AVoidedVolumeFiveTimesTheInfusedIsRefused) {
  auto r = shared();
  scale(r.voided_ml, 5.0);
  EXPECT_EQ(refusing_rule(r), "voided-exceeds-infused");
}

TEST(Plausibility, SomewhatMoreVoidedThanInfusedIsAWarning) {
  auto r = shared();
  scale(r.voided_ml, 1.3);  // 455 ml voided of 349 infused: urine made during the study
  EXPECT_EQ(refusing_rule(r), "");
  const auto rules = warned_rules(r);
  EXPECT_NE(std::find(rules.begin(), rules.end(), "voided-exceeds-infused"), rules.end());
}

TEST(Plausibility, FlowWithoutAVoidedColumnGivesTheResidualFromTheFlow) {
  auto r = shared();
  r.voided_ml.clear();
  const vc::RecordingAnalysis a = vc::analyse_checked(r);
  // Voided is the flow's trapezoidal integral; the residual what is left of the 349 ml
  // infused, not the whole capacity.
  ASSERT_TRUE(a.ics.voided_ml && a.ics.pvr_ml);
  double integral = 0;
  for (std::size_t i = 1; i < r.rows(); ++i)
    integral += 0.5 * (r.flow_ml_s[i] + r.flow_ml_s[i - 1]) * (r.time_s[i] - r.time_s[i - 1]);
  EXPECT_NEAR(*a.ics.voided_ml, integral, 1e-9);
  EXPECT_NEAR(*a.ics.pvr_ml, std::max(0.0, 349.0 - integral), 1e-9);
  EXPECT_LT(*a.ics.pvr_ml, 349.0);
}

TEST(Plausibility, AWarningIsCarriedIntoTheReportAndItsMetrics) {
  const fs::path dir = vesica::test::scratch_dir("plausibility-report");
  fs::remove_all(dir);
  fs::create_directories(dir);
  // The shared recording with its voided column 1.3 times larger, as a file.
  vesica::test::write_edited_recording(
      compare_data("normal-female-34y.csv"), dir / "more-voided.csv",
      [](std::vector<std::string>& cells) {
        cells[6] = std::to_string(1.3 * std::stod(cells[6]));  // voided_ml
      });
  const auto r = vesica::test::run_command(vesica::test::compare_exe() + " --measured '" +
                                           (dir / "more-voided.csv").string() + "' -o '" +
                                           (dir / "report").string() + "' --no-pdf");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto metrics =
      nlohmann::json::parse(vesica::test::read_text(dir / "report" / "metrics.json"));
  ASSERT_EQ(metrics["measured"]["plausibility_warnings"].size(), 1u);
  EXPECT_EQ(metrics["measured"]["plausibility_warnings"][0]["rule"], "voided-exceeds-infused");
  const std::string page = vesica::test::read_text(dir / "report" / "index.html");
  EXPECT_NE(page.find("Check the recording"), std::string::npos);
  EXPECT_NE(page.find("voided-exceeds-infused"), std::string::npos);
}
