// The study's read-outs on a hand-made cystometry whose answers are worked out by hand
// (volumes ml, pressures cmH2O, flow ml/s): filling 100 -> 500 ml, then a voiding whose
// Pdet peak (65) is above anything reached while filling.
#include <gtest/gtest.h>

#include "PipelineTestSupport.h"
#include "vesica/core/Error.h"
#include "vesica/pipelines/CystometryCurve.h"

namespace fs = std::filesystem;
using namespace vesica::pipelines;
using namespace vesica::test;

namespace {

// time_s, infused_ml, volume_ml, pves, pabd, pdet, flow_ml_s, voided_ml — as vesica-simulate
// writes it. Filling ends at row 6 (500 ml); rows 7-10 are voiding.
const char* kHistory =
    "time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,flow_ml_s,voided_ml\n"
    "0,0,100,0,0,0,0,0\n"
    "60,50,150,2,0,2,0,0\n"
    "120,100,200,5,0,5,0,0\n"
    "240,200,300,10,0,10,0,0\n"
    "360,300,400,30,0,30,0,0\n"
    "420,350,450,50,0,50,0,0\n"
    "480,400,500,60,0,60,0,0\n"
    "481,400,480,101.7,36.7,65,20,20\n"
    "482,400,450,91.7,36.7,55,30,50\n"
    "483,400,440,56.7,36.7,20,10,60\n"
    "485,400,439,41.7,36.7,5,0,61\n";

CystometryCurve hand_made_curve(const std::string& name) {
  const fs::path csv = scratch_dir(name) / "history.csv";
  write_text(csv, kHistory);
  return read_history_csv(csv);
}

}  // namespace

TEST(CystometryCurve, ReadsTheColumnsItNeeds) {
  const CystometryCurve c = hand_made_curve("curve-read");
  ASSERT_EQ(c.size(), 11u);
  EXPECT_EQ(c.volume_ml[3], 300.0);
  EXPECT_EQ(c.pdet_cmh2o[7], 65.0);
  EXPECT_EQ(c.flow_ml_s[8], 30.0);
  EXPECT_EQ(c.filling_end(), 6u);
}

TEST(CystometryCurve, PdetAtVolumeInterpolatesTheFillingCurve) {
  const CystometryCurve c = hand_made_curve("curve-pdet");
  EXPECT_DOUBLE_EQ(*filling_pdet_at_volume(c, 300.0), 10.0);  // a row
  EXPECT_DOUBLE_EQ(*filling_pdet_at_volume(c, 250.0), 7.5);   // half-way 5 -> 10
  EXPECT_DOUBLE_EQ(*filling_pdet_at_volume(c, 500.0), 60.0);  // the last filling row
  EXPECT_DOUBLE_EQ(*filling_pdet_at_volume(c, 100.0), 0.0);   // the first row
  EXPECT_FALSE(filling_pdet_at_volume(c, 500.1));             // never filled that far
  EXPECT_FALSE(filling_pdet_at_volume(c, 90.0));              // below the start of filling
}

TEST(CystometryCurve, CapacityAtPressureIsTheFirstFillingCrossing) {
  const CystometryCurve c = hand_made_curve("curve-capacity");
  EXPECT_DOUBLE_EQ(*filling_volume_at_pdet(c, 40.0), 425.0);  // 400 ml @ 30, 450 ml @ 50
  EXPECT_DOUBLE_EQ(*filling_volume_at_pdet(c, 60.0), 500.0);
  // 62 cmH2O is reached only while voiding (65): no filling capacity at that pressure.
  EXPECT_FALSE(filling_volume_at_pdet(c, 62.0));
}

TEST(CystometryCurve, ComplianceAndMaximumPressure) {
  const CystometryCurve c = hand_made_curve("curve-compliance");
  EXPECT_DOUBLE_EQ(*filling_compliance(c), 400.0 / 60.0);  // (500 - 100) ml / (60 - 0) cmH2O
  EXPECT_DOUBLE_EQ(*max_pdet(c), 65.0);                    // the voiding peak counts
  EXPECT_DOUBLE_EQ(*voiding_qmax(c), 30.0);
  CystometryCurve filling_only = c;
  for (auto* column : {&filling_only.time_s, &filling_only.volume_ml, &filling_only.pdet_cmh2o,
                       &filling_only.flow_ml_s})
    column->resize(7);
  EXPECT_FALSE(voiding_qmax(filling_only));
  EXPECT_FALSE(filling_compliance(CystometryCurve{}));
  EXPECT_FALSE(max_pdet(CystometryCurve{}));
}

TEST(CystometryCurve, BadFileIsOneErrorNamingIt) {
  const fs::path dir = scratch_dir("curve-bad");
  write_text(dir / "nocol.csv", "time_s,volume_ml,flow_ml_s\n0,1,0\n");
  try {
    read_history_csv(dir / "nocol.csv");
    FAIL() << "no error";
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find("nocol.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("pdet_cmh2o"), std::string::npos) << e.what();
  }
  write_text(dir / "text.csv", "time_s,volume_ml,pdet_cmh2o,flow_ml_s\n0,1,x,0\n");
  EXPECT_THROW(read_history_csv(dir / "text.csv"), vesica::Error);
}
