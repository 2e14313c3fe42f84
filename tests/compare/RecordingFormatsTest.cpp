// Recordings as papers and charts print them: a filling table read off at infused-volume
// steps and a voiding table of Pdet and flow against the voided volume, neither with a time
// column. The ICS values below are worked out by hand from the fixtures' rows
// (tests/compare/data) with the definitions of docs/compare.md; what needs time is absent
// and said so.
#include <fstream>

#include <gtest/gtest.h>

#include "TestData.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/core/Error.h"
#include "vesica/io/RecordingReader.h"

namespace vc = vesica::compare;

namespace {

std::filesystem::path data(const std::string& name) {
  return vesica::test::source_dir() / "tests/compare/data" / name;
}

bool has_note(const vc::IcsParameters& p, const std::string& text) {
  for (const auto& n : p.notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

std::string reader_error(const std::string& name, const std::string& text) {
  const auto path = vesica::test::scratch_dir("formats-" + name) / (name + ".csv");
  std::ofstream(path) << text;
  try {
    vesica::io::read_recording(path);
  } catch (const vesica::Error& e) {
    return e.problem();
  }
  return "";
}

}  // namespace

TEST(RecordingFormats, AFillingTableWithoutTimeGivesItsFillingParameters) {
  const auto a = vc::analyse(vesica::io::read_recording(data("filling-table.csv")));
  const auto& p = a.ics;
  EXPECT_FALSE(a.recording.has_time());
  EXPECT_EQ(a.recording.rows(), 8u);
  EXPECT_TRUE(a.flags.empty());
  EXPECT_DOUBLE_EQ(*p.volume_start_ml, 0);
  EXPECT_DOUBLE_EQ(*p.pdet_start_cmh2o, 2);
  EXPECT_DOUBLE_EQ(*p.capacity_ml, 350);
  EXPECT_DOUBLE_EQ(*p.pdet_capacity_cmh2o, 10);
  EXPECT_DOUBLE_EQ(*p.compliance_ml_per_cmh2o, 350.0 / 8.0);  // 43.75 ml/cmH2O
  EXPECT_DOUBLE_EQ(*p.first_desire_ml, 100);
  EXPECT_DOUBLE_EQ(*p.normal_desire_ml, 200);
  EXPECT_DOUBLE_EQ(*p.strong_desire_ml, 300);
  EXPECT_FALSE(p.fill_rate_ml_min);  // nothing to infer it from
  EXPECT_FALSE(p.qmax_ml_s);
  ASSERT_EQ(a.filling.x.size(), 8u);
  EXPECT_DOUBLE_EQ(a.filling.y[6], 8);  // the 300 ml row
}

TEST(RecordingFormats, AGivenFillRateIsTheRecordingsRate) {
  vc::RecordingFacts facts;
  facts.fill_rate_ml_min = 30;
  const auto a = vc::analyse(vesica::io::read_recording(data("filling-table.csv")), {}, facts);
  EXPECT_DOUBLE_EQ(*a.ics.fill_rate_ml_min, 30);
}

TEST(RecordingFormats, TheFillRateOfATimedRecordingIsInferred) {
  // The shared recording: 25 ml at 00:45 to 349 ml at 06:20 in 25 ml steps of about 26 s;
  // the least-squares slope over its 17 filling rows, worked out from the rows:
  // Σ(t - t̄)(V - V̄)/Σ(t - t̄)² = 0.9662 ml/s = 57.97 ml/min (its header says 50 ml/min).
  const auto a = vc::analyse(vesica::io::read_recording(data("normal-female-34y.csv")));
  ASSERT_TRUE(a.ics.fill_rate_ml_min);
  EXPECT_NEAR(*a.ics.fill_rate_ml_min, 58.0, 0.1);
}

TEST(RecordingFormats, AVoidingTableGivesThePressureFlowParametersThatNeedNoTime) {
  vc::RecordingFacts facts;
  facts.capacity_ml = 320;
  const auto a = vc::analyse(vesica::io::read_recording(data("voiding-table.csv")), {}, facts);
  const auto& p = a.ics;
  EXPECT_DOUBLE_EQ(*p.voided_ml, 300);
  EXPECT_DOUBLE_EQ(*p.pvr_ml, 20);  // 320 before voiding - 300 voided
  EXPECT_DOUBLE_EQ(*p.voiding_efficiency, 300.0 / 320.0);
  EXPECT_DOUBLE_EQ(*p.qmax_ml_s, 22);               // the 150 ml row
  EXPECT_DOUBLE_EQ(*p.pdet_qmax_cmh2o, 38);         // at that row
  EXPECT_DOUBLE_EQ(*p.pdet_opening_cmh2o, 32);      // 25 ml, the first row with flow
  EXPECT_DOUBLE_EQ(*p.pdet_closing_cmh2o, 30);      // 290 ml, the last row with flow
  EXPECT_DOUBLE_EQ(*p.pdet_max_voiding_cmh2o, 40);  // 100 ml
  EXPECT_DOUBLE_EQ(*p.booi, 38 - 2 * 22);           // -6
  EXPECT_EQ(p.booi_class, "unobstructed");
  EXPECT_DOUBLE_EQ(*p.bci, 38 + 5 * 22);  // 148
  EXPECT_EQ(p.bci_class, "normal");
  // what needs time is left out, and the report says why
  EXPECT_FALSE(p.flow_time_s);
  EXPECT_FALSE(p.voiding_time_s);
  EXPECT_FALSE(p.qave_ml_s);
  EXPECT_FALSE(p.time_to_qmax_s);
  EXPECT_FALSE(p.voiding_start_s);
  EXPECT_TRUE(has_note(p, "no time column"));
}

TEST(RecordingFormats, AVoidingTableWithoutVolumeAssumesNoResidualAndSaysSo) {
  const auto a = vc::analyse(vesica::io::read_recording(data("voiding-table.csv")));
  EXPECT_DOUBLE_EQ(*a.ics.capacity_ml, 300);
  EXPECT_DOUBLE_EQ(*a.ics.pvr_ml, 0);
  EXPECT_TRUE(has_note(a.ics, "no residual"));
}

TEST(RecordingFormats, ATableWithoutTimeMustBeSortedByItsVolume) {
  const auto m = reader_error("unsorted", "infused_ml,pdet_cmh2o\n0,1\n100,2\n50,3\n");
  EXPECT_NE(m.find("row 4, column \"infused_ml\""), std::string::npos) << m;
  EXPECT_NE(m.find("below the row before it"), std::string::npos) << m;
}

TEST(RecordingFormats, ATableWithNeitherTimeNorVolumeIsRefused) {
  const auto m = reader_error("no-index", "pdet_cmh2o,flow_ml_s\n1,0\n2,3\n");
  EXPECT_NE(m.find("missing column for time, or for the volume"), std::string::npos) << m;
}
