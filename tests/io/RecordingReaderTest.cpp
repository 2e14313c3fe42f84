// The CSV reader: the shared recording's layout (mm:ss, comments, event labels), units,
// column maps, and one-line errors naming file, row and column.
#include <fstream>

#include <gtest/gtest.h>

#include "TestData.h"
#include "vesica/core/Error.h"
#include "vesica/io/RecordingReader.h"

namespace vc = vesica::io;
namespace fs = std::filesystem;

namespace {

fs::path data(const std::string& name) {
  return vesica::test::source_dir() / "tests/compare/data" / name;
}

fs::path write_csv(const std::string& test, const std::string& text) {
  const fs::path p = vesica::test::scratch_dir(test) / "rec.csv";
  std::ofstream(p) << text;
  return p;
}

// The message of the vesica::Error that reading `text` throws.
std::string error_of(const std::string& test, const std::string& text,
                     const vc::ReaderOptions& o = {}) {
  const fs::path p = write_csv(test, text);
  try {
    vc::read_recording(p, o);
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error for " << text;
  return {};
}

}  // namespace

TEST(RecordingReader, ReadsTheClinicalRecording) {
  const auto r = vc::read_recording(data("normal-female-34y.csv"));
  ASSERT_EQ(r.rows(), 31u);                        // 37 lines: 5 comments, 1 header
  EXPECT_DOUBLE_EQ(r.time_s.front(), 45.0);        // 00:45
  EXPECT_DOUBLE_EQ(r.time_s.back(), 7 * 60 + 19);  // 07:19
  EXPECT_EQ(r.line.front(), 7);
  EXPECT_EQ(r.event[13], "strong desire");
  EXPECT_DOUBLE_EQ(r.pves_cmh2o[13], 19);
  EXPECT_DOUBLE_EQ(r.pabd_cmh2o[13], 16);
  EXPECT_DOUBLE_EQ(r.pdet_recorded_cmh2o[16], 5);
  EXPECT_DOUBLE_EQ(r.infused_ml.back(), 349);
  EXPECT_DOUBLE_EQ(r.voided_ml.back(), 350);
  EXPECT_DOUBLE_EQ(r.flow_ml_s[22], 17);
  EXPECT_TRUE(r.volume_ml.empty());
}

TEST(RecordingReader, ReadsTheSimulationHistoryWithTheSameCode) {
  const auto r = vc::read_recording(data("synthetic-history.csv"));
  ASSERT_EQ(r.rows(), 401u);
  EXPECT_DOUBLE_EQ(r.volume_ml.front(), 50);
  EXPECT_DOUBLE_EQ(r.pdet_recorded_cmh2o[360], 5);
  EXPECT_TRUE(r.event.empty());
}

TEST(RecordingReader, ConvertsUnitsAndMapsColumns) {
  const auto p = write_csv("reader-units",
                           "t,Pves [kPa],abd_pa,V_l,Q_ml_min,note\n"
                           "1:00,0.980665,98.0665,0.1,60,\"cough, strong\"\n"
                           "1:30.5,1.96133,196.133,0.2,120,\n");
  vc::ReaderOptions o;
  o.columns = vc::parse_column_map(
      "time=t,pves=Pves [kPa],pabd=abd_pa,infused=V_l,flow=Q_ml_min,event=note");
  const auto r = vc::read_recording(p, o);
  EXPECT_DOUBLE_EQ(r.time_s[1], 90.5);
  EXPECT_NEAR(r.pves_cmh2o[0], 10.0, 1e-12);  // 0.980665 kPa = 10 cmH2O
  EXPECT_NEAR(r.pabd_cmh2o[1], 2.0, 1e-12);   // 196.133 Pa = 2 cmH2O
  EXPECT_NEAR(r.infused_ml[1], 200.0, 1e-12);
  EXPECT_NEAR(r.flow_ml_s[1], 2.0, 1e-12);
  EXPECT_EQ(r.event[0], "cough, strong");
}

TEST(RecordingReader, UnsuffixedPressuresUseThePressureUnit) {
  const auto p =
      write_csv("reader-default-unit", "time,pves,pabd,infused_ml\n0,1,0.5,0\n1,2,1,1\n");
  vc::ReaderOptions o;
  o.pressure_unit = "kpa";
  EXPECT_NEAR(vc::read_recording(p, o).pves_cmh2o[1], 2000 / 98.0665, 1e-12);
}

TEST(RecordingReader, ParsesClockTimes) {
  EXPECT_DOUBLE_EQ(*vc::parse_clock_time("06:20"), 380);
  EXPECT_DOUBLE_EQ(*vc::parse_clock_time("1:00:01.5"), 3601.5);
  EXPECT_FALSE(vc::parse_clock_time("6:75"));
  EXPECT_FALSE(vc::parse_clock_time("ab:10"));
}

TEST(RecordingReader, MissingColumnIsNamed) {
  const auto m = error_of("reader-missing", "time_s,pves_cmh2o,infused_ml\n0,1,0\n1,2,1\n");
  EXPECT_NE(m.find("missing columns for pressure"), std::string::npos) << m;
  const auto mapped = [] {
    vc::ReaderOptions o;
    o.columns = vc::parse_column_map("pves=Pves");
    return o;
  }();
  const auto m2 = error_of("reader-missing-mapped",
                           "time_s,pves_cmh2o,pabd_cmh2o,infused_ml\n0,1,0,0\n1,2,1,1\n", mapped);
  EXPECT_NE(m2.find("missing column \"Pves\""), std::string::npos) << m2;
}

TEST(RecordingReader, NonNumericCellNamesRowAndColumn) {
  const auto m = error_of(
      "reader-nan", "# comment\ntime_s,pves_cmh2o,pabd_cmh2o,infused_ml\n0,1,0,0\n1,x2,1,1\n");
  EXPECT_NE(m.find("row 4, column \"pves_cmh2o\": \"x2\" is not a number"), std::string::npos) << m;
}

TEST(RecordingReader, UnsortedTimeNamesRowAndColumn) {
  const auto m =
      error_of("reader-unsorted", "time,pdet_cmh2o,infused_ml\n00:10,1,0\n00:20,1,1\n00:15,1,2\n");
  EXPECT_NE(m.find("row 4, column \"time\""), std::string::npos) << m;
  EXPECT_NE(m.find("goes back in time"), std::string::npos) << m;
}

TEST(RecordingReader, UnknownUnitNamesColumn) {
  const auto m =
      error_of("reader-unit", "time_s,pves_psi,pabd_cmh2o,infused_ml\n0,1,0,0\n1,2,1,1\n");
  EXPECT_NE(m.find("column \"pves_psi\": unknown unit \"psi\""), std::string::npos) << m;
  vc::ReaderOptions o;
  o.pressure_unit = "bar";
  const auto m2 = error_of("reader-unit2", "time,pves,pabd,infused_ml\n0,1,0,0\n1,2,1,1\n", o);
  EXPECT_NE(m2.find("unknown pressure unit \"bar\""), std::string::npos) << m2;
}

TEST(RecordingReader, ShortRowIsNamed) {
  const auto m = error_of("reader-short", "time_s,pdet_cmh2o,infused_ml\n0,1,0\n1,2\n");
  EXPECT_NE(m.find("row 3: 2 cells"), std::string::npos) << m;
}

// Spreadsheet programs save "CSV UTF-8" with a byte-order mark before the header.
TEST(RecordingReader, ByteOrderMarkOfASpreadsheetExportIsIgnored) {
  const auto p =
      write_csv("reader-bom", "\xEF\xBB\xBFtime_s,pdet_cmh2o,infused_ml\n0,1,0\n10,2,50\n");
  const auto r = vc::read_recording(p);
  ASSERT_EQ(r.rows(), 2u);
  EXPECT_DOUBLE_EQ(r.time_s[1], 10);
  EXPECT_DOUBLE_EQ(r.pdet_recorded_cmh2o[1], 2);
  EXPECT_DOUBLE_EQ(r.infused_ml[1], 50);
}

// The ICS standard's channel names, as the shared recording's own notes name them, read
// without --columns.
TEST(RecordingReader, IcsChannelNamesReadWithoutAColumnMap) {
  const fs::path p = write_csv("reader-ics",
                               "Time,Pves,Pabd,Pdet,Qura,Vura,Vinf\n"
                               "00:10,10,4,6,0,0,25\n"
                               "00:40,14,5,9,12.5,30,300\n");
  const vc::Recording r = vc::read_recording(p);
  ASSERT_EQ(r.rows(), 2u);
  EXPECT_EQ(r.time_s, (std::vector<double>{10, 40}));
  EXPECT_EQ(r.pves_cmh2o, (std::vector<double>{10, 14}));
  EXPECT_EQ(r.pabd_cmh2o, (std::vector<double>{4, 5}));
  EXPECT_EQ(r.pdet_recorded_cmh2o, (std::vector<double>{6, 9}));
  EXPECT_EQ(r.flow_ml_s, (std::vector<double>{0, 12.5}));
  EXPECT_EQ(r.voided_ml, (std::vector<double>{0, 30}));
  EXPECT_EQ(r.infused_ml, (std::vector<double>{25, 300}));
}

// A European export: ';' between cells, decimal commas, units in brackets, and the ICS name
// glossed in brackets after a plain one ("flow (Qura)").
TEST(RecordingReader, SemicolonsDecimalCommasAndBracketedUnitsReadWithoutAColumnMap) {
  const fs::path p = write_csv("reader-european",
                               "Time (s);Pves (cmH2O);Pabd (cmH2O);Pdet (kPa);flow (Qura);"
                               "voided volume (Vura);Vinf (ml)\n"
                               "0;12,5;3,0;1;0;0;0\n"
                               "1,5;13,5;4,5;0,5;2,5;1,25;40\n");
  const vc::Recording r = vc::read_recording(p);
  ASSERT_EQ(r.rows(), 2u);
  EXPECT_EQ(r.time_s, (std::vector<double>{0, 1.5}));
  EXPECT_EQ(r.pves_cmh2o, (std::vector<double>{12.5, 13.5}));
  EXPECT_EQ(r.pabd_cmh2o, (std::vector<double>{3, 4.5}));
  // 1 kPa = 1000 / (1000 kg/m3 * 9.80665 m/s2 * 0.01 m) cmH2O = 10.1972 cmH2O
  EXPECT_NEAR(r.pdet_recorded_cmh2o[0], 10.1972, 1e-4);
  EXPECT_NEAR(r.pdet_recorded_cmh2o[1], 5.0986, 1e-4);
  EXPECT_EQ(r.flow_ml_s, (std::vector<double>{0, 2.5}));
  EXPECT_EQ(r.voided_ml, (std::vector<double>{0, 1.25}));
  EXPECT_EQ(r.infused_ml, (std::vector<double>{0, 40}));
}

// However many columns a file has, the one-line error keeps what to do about them.
TEST(RecordingReader, MissingChannelErrorKeepsItsFixAfterALongHeader) {
  std::string header = "time_s";
  for (int i = 0; i < 40; ++i) header += ",channel_number_" + std::to_string(i);
  std::string row = "0";
  for (int i = 0; i < 40; ++i) row += ",1";
  const auto m = error_of("reader-long-header", header + "\n" + row + "\n" + row + "\n");
  EXPECT_NE(m.find("missing columns for pressure"), std::string::npos) << m;
  EXPECT_NE(m.find("map one with --columns KEY=NAME"), std::string::npos) << m;
  EXPECT_LE(m.size(), vesica::kMaxErrorLine);
}
