// ICS parameters against hand-checked values: the shared clinical recording (numbers
// worked out by hand from its 31 rows with the definitions of docs/compare.md) and a
// synthetic history whose parameters are known analytically.
#include <cmath>

#include <gtest/gtest.h>

#include "TestData.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/io/RecordingReader.h"

namespace vc = vesica::compare;

namespace {
vc::RecordingAnalysis analysed(const std::string& name) {
  return vc::analyse(
      vesica::io::read_recording(vesica::test::source_dir() / "tests/compare/data" / name));
}
}  // namespace

TEST(IcsParameters, ClinicalRecordingFilling) {
  const auto a = analysed("normal-female-34y.csv");
  const auto& p = a.ics;
  EXPECT_EQ(a.recording.event[p.capacity_row], "350 ml");  // first row at 349 ml infused
  EXPECT_DOUBLE_EQ(*p.capacity_ml, 349);
  EXPECT_DOUBLE_EQ(*p.volume_start_ml, 25);
  EXPECT_DOUBLE_EQ(*p.pdet_start_cmh2o, 2);
  EXPECT_DOUBLE_EQ(*p.pdet_capacity_cmh2o, 5);
  EXPECT_DOUBLE_EQ(*p.compliance_ml_per_cmh2o, (349.0 - 25.0) / (5.0 - 2.0));  // 108
  EXPECT_DOUBLE_EQ(*p.normal_desire_ml, 262);
  EXPECT_DOUBLE_EQ(*p.strong_desire_ml, 311);
  EXPECT_FALSE(p.first_desire_ml);
}

TEST(IcsParameters, ClinicalRecordingVoiding) {
  const auto p = analysed("normal-female-34y.csv").ics;
  EXPECT_DOUBLE_EQ(*p.qmax_ml_s, 17);
  EXPECT_DOUBLE_EQ(*p.pdet_qmax_cmh2o, 5);
  EXPECT_DOUBLE_EQ(*p.voided_ml, 350);
  EXPECT_DOUBLE_EQ(*p.pvr_ml, 0);  // 349 infused - 350 voided, clamped at zero
  EXPECT_DOUBLE_EQ(*p.voiding_efficiency, 1.0);
  EXPECT_DOUBLE_EQ(*p.booi, -29);
  EXPECT_EQ(p.booi_class, "unobstructed");
  EXPECT_DOUBLE_EQ(*p.bci, 90);
  EXPECT_EQ(p.bci_class, "weak");
  // flow is positive from 06:40 (the sample before the first flow) to 07:19
  EXPECT_DOUBLE_EQ(*p.voiding_start_s, 6 * 60 + 40);
  EXPECT_DOUBLE_EQ(*p.flow_time_s, 39);
  EXPECT_DOUBLE_EQ(*p.voiding_time_s, 39);
  EXPECT_DOUBLE_EQ(*p.qave_ml_s, 350.0 / 39.0);
  EXPECT_DOUBLE_EQ(*p.time_to_qmax_s, 11);          // 06:51 - 06:40
  EXPECT_DOUBLE_EQ(*p.pdet_opening_cmh2o, 0);       // 06:43, first row with flow
  EXPECT_DOUBLE_EQ(*p.pdet_max_voiding_cmh2o, 26);  // 07:14
  EXPECT_DOUBLE_EQ(*p.pdet_closing_cmh2o, 10);      // 07:19, last row with flow
}

TEST(IcsParameters, FlagsTheStrongDesireRowAsAbdominalSpike) {
  const auto a = analysed("normal-female-34y.csv");
  ASSERT_EQ(a.flags.size(), 2u);
  EXPECT_EQ(a.flags[0].event, "strong desire");
  EXPECT_EQ(a.flags[0].kind, "abdominal spike");
  EXPECT_EQ(a.flags[0].line, 20);
  // Pabd 20 over Pves 18 at "initial voiding pressure": straining, negative Pdet
  EXPECT_EQ(a.flags[1].event, "initial voiding pressure");
  EXPECT_EQ(a.flags[1].kind, "straining");
  // flagged rows stay out of the filling curve: 17 filling rows, 1 flagged
  EXPECT_EQ(a.filling.x.size(), 16u);
}

TEST(IcsParameters, SyntheticHistoryMatchesItsAnalyticValues) {
  const auto a = analysed("synthetic-history.csv");
  const auto& p = a.ics;
  EXPECT_TRUE(a.flags.empty());
  EXPECT_DOUBLE_EQ(*p.capacity_ml, 350);
  EXPECT_NEAR(*p.compliance_ml_per_cmh2o, 100, 1e-9);
  EXPECT_DOUBLE_EQ(*p.qmax_ml_s, 18);
  EXPECT_DOUBLE_EQ(*p.pdet_qmax_cmh2o, 25);
  EXPECT_NEAR(*p.voided_ml, 1080 / M_PI, 1e-4);
  EXPECT_NEAR(*p.pvr_ml, 350 - 1080 / M_PI, 1e-4);
  EXPECT_DOUBLE_EQ(*p.flow_time_s, 30);
  EXPECT_DOUBLE_EQ(*p.time_to_qmax_s, 15);
  EXPECT_DOUBLE_EQ(*p.booi, 25 - 36);
  EXPECT_DOUBLE_EQ(*p.bci, 25 + 90);
  EXPECT_EQ(p.bci_class, "normal");
}

TEST(IcsParameters, ClassBoundaries) {
  EXPECT_EQ(vc::booi_class(41), "obstructed");
  EXPECT_EQ(vc::booi_class(40), "equivocal");
  EXPECT_EQ(vc::booi_class(20), "equivocal");
  EXPECT_EQ(vc::booi_class(19.9), "unobstructed");
  EXPECT_EQ(vc::bci_class(151), "strong");
  EXPECT_EQ(vc::bci_class(100), "normal");
  EXPECT_EQ(vc::bci_class(99), "weak");
}

// A simulated bladder held at capacity through an isovolumetric contraction keeps its
// volume to the solver's tolerance only: capacity is where filling ended (t = 2 s, 350 ml),
// not the last row of the contraction; flow starts in the interval from 4 s (the linear
// interpolant is positive on it), 2 s after capacity.
TEST(IcsParameters, CapacityIsTheEndOfFillingWhenTheContractionCreepsBySolverTolerance) {
  vesica::io::Recording r;
  r.time_s = {0, 1, 2, 3, 4, 5, 6, 7};
  r.volume_ml = {300, 325, 350, 350 + 2e-10, 350 + 5e-10, 348, 340, 335};
  r.pves_cmh2o = {10, 11, 12, 20, 30, 32, 31, 30};
  r.pabd_cmh2o = std::vector<double>(8, 8.0);
  r.flow_ml_s = {0, 0, 0, 0, 0, 2, 8, 5};
  r.voided_ml = {0, 0, 0, 0, 0, 2, 10, 15};
  r.infused_ml = {250, 275, 300, 300, 300, 300, 300, 300};
  const vc::RecordingAnalysis a = vc::analyse(r);
  EXPECT_EQ(a.ics.capacity_row, 2u);
  ASSERT_TRUE(a.ics.voiding_start_s.has_value());
  EXPECT_DOUBLE_EQ(*a.ics.voiding_start_s - r.time_s[a.ics.capacity_row], 2.0);
}
