// history.csv: the text vesica-simulate writes (checked against a hand-written file) and
// the values read back through the recording reader that compare and the runner use.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "TestData.h"
#include "vesica/core/Error.h"
#include "vesica/io/HistoryCsv.h"

namespace {

namespace fs = std::filesystem;
using vesica::io::HistoryRow;

// Two steps of a cystometry; every value has at most 10 significant digits, so the file
// holds it exactly.
std::vector<HistoryRow> two_steps() {
  return {{0.0, 0.0, 50.0, 6.0, 4.0, 2.0, 0.0, 0.0},
          {12.5, 10.41666667, 60.41666667, 6.104166667, 4.0, 2.104166667, 0.0, 0.0}};
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HistoryCsv, WrittenTextIsTheDocumentedLayout) {
  const fs::path csv = vesica::test::scratch_dir("io-history-text") / "history.csv";
  vesica::io::write_history_csv(two_steps(), csv);
  EXPECT_EQ(read_text(csv),
            "time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,flow_ml_s,voided_ml\n"
            "0,0,50,6,4,2,0,0\n"
            "12.5,10.41666667,60.41666667,6.104166667,4,2.104166667,0,0\n");
}

TEST(HistoryCsv, RoundTripGivesTheSameRows) {
  const fs::path csv = vesica::test::scratch_dir("io-history-roundtrip") / "history.csv";
  const std::vector<HistoryRow> rows = two_steps();
  vesica::io::write_history_csv(rows, csv);
  const std::vector<HistoryRow> back = vesica::io::history_rows(vesica::io::read_history_csv(csv));
  ASSERT_EQ(back.size(), rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_EQ(back[i].time_s, rows[i].time_s);
    EXPECT_EQ(back[i].infused_ml, rows[i].infused_ml);
    EXPECT_EQ(back[i].volume_ml, rows[i].volume_ml);
    EXPECT_EQ(back[i].pves_cmh2o, rows[i].pves_cmh2o);
    EXPECT_EQ(back[i].pabd_cmh2o, rows[i].pabd_cmh2o);
    EXPECT_EQ(back[i].pdet_cmh2o, rows[i].pdet_cmh2o);
    EXPECT_EQ(back[i].flow_ml_s, rows[i].flow_ml_s);
    EXPECT_EQ(back[i].voided_ml, rows[i].voided_ml);
  }
}

TEST(HistoryCsv, FailedRunWithOnlyTheHeaderIsReadAsEmpty) {
  const fs::path csv = vesica::test::scratch_dir("io-history-empty") / "history.csv";
  vesica::io::write_history_csv({}, csv);
  EXPECT_EQ(vesica::io::read_history_csv(csv).rows(), 0u);
}

TEST(HistoryCsv, MissingFlowColumnIsNamed) {
  const fs::path csv = vesica::test::scratch_dir("io-history-noflow") / "history.csv";
  std::ofstream(csv) << "time_s,volume_ml,pdet_cmh2o\n0,50,2\n1,51,2.1\n";
  try {
    vesica::io::read_history_csv(csv);
    FAIL() << "no error";
  } catch (const vesica::Error& e) {
    EXPECT_NE(std::string(e.what()).find("history.csv"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("flow_ml_s"), std::string::npos) << e.what();
  }
}

}  // namespace
