// Recordings as spreadsheets export them in Europe (a byte-order mark, ';' separators,
// decimal commas) are read as their comma-separated twins; hostile ones (a 5 MB cell,
// millions of rows, a binary file) are refused with one short line before they cost
// memory.
#include <fstream>

#include <gtest/gtest.h>

#include "TestData.h"
#include "vesica/core/Error.h"
#include "vesica/io/CsvTable.h"
#include "vesica/io/RecordingReader.h"

namespace vc = vesica::io;
namespace fs = std::filesystem;

namespace {

fs::path write_file(const std::string& test, const std::string& text) {
  const fs::path p = vesica::test::scratch_dir(test) / "rec.csv";
  std::ofstream(p, std::ios::binary) << text;
  return p;
}

std::string error_of(const fs::path& p, const vc::CsvOptions& options = {}) {
  try {
    vc::read_csv_table(p, options);
    vc::read_recording(p);
  } catch (const vesica::Error& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for " << p;
  return {};
}

}  // namespace

TEST(HostileCsv, AEuropeanExportReadsAsItsCommaSeparatedTwin) {
  const auto comma = vc::read_recording(write_file(
      "csv-comma", "time_s,pves_cmh2o,pabd_cmh2o,infused_ml\n0,10.5,8.25,0\n1.5,11,8.5,1.25\n"));
  const auto european = vc::read_recording(write_file(
      "csv-european",
      "\xEF\xBB\xBFtime_s;pves_cmh2o;pabd_cmh2o;infused_ml\r\n0;10,5;8,25;0\r\n1,5;11;8,5;1,25\r\n"
      ";;;\r\n"));
  EXPECT_EQ(european.time_s, comma.time_s);
  EXPECT_EQ(european.pves_cmh2o, comma.pves_cmh2o);
  EXPECT_EQ(european.pabd_cmh2o, comma.pabd_cmh2o);
  EXPECT_EQ(european.infused_ml, comma.infused_ml);
  EXPECT_DOUBLE_EQ(european.pves_cmh2o[0], 10.5);
  EXPECT_DOUBLE_EQ(european.infused_ml[1], 1.25);
}

TEST(HostileCsv, TabSeparatedReadsToo) {
  const auto r = vc::read_recording(
      write_file("csv-tabs", "time_s\tpdet_cmh2o\tinfused_ml\n0\t2,5\t0\n1\t3\t1\n"));
  EXPECT_DOUBLE_EQ(r.pdet_recorded_cmh2o[0], 2.5);
}

TEST(HostileCsv, AnAmbiguousGroupedNumberIsRefusedNotGuessed) {
  const std::string error =
      error_of(write_file("csv-grouped", "time_s;pdet_cmh2o;infused_ml\n0;1.234,5;0\n1;3;1\n"));
  EXPECT_NE(error.find("\"1.234,5\" is not a number"), std::string::npos) << error;
}

TEST(HostileCsv, AFiveMegabyteCellGivesOneShortLine) {
  const std::string cell(5 * 1024 * 1024, '9');
  const fs::path p =
      write_file("csv-huge-cell", "time_s,pdet_cmh2o,infused_ml\n0," + cell + ",0\n");
  const std::string error = error_of(p);
  EXPECT_LE(error.size(), vesica::kMaxErrorLine);
  EXPECT_NE(error.find("line 2 is longer than 65536 bytes"), std::string::npos) << error;
}

TEST(HostileCsv, ALongCellWithinTheLineLimitIsQuotedShort) {
  const std::string cell(20000, 'x');
  const std::string error =
      error_of(write_file("csv-long-cell", "time_s,pdet_cmh2o,infused_ml\n0," + cell + ",0\n"));
  EXPECT_LE(error.size(), vesica::kMaxErrorLine);
  EXPECT_NE(error.find("row 2, column \"pdet_cmh2o\": \"xxxx"), std::string::npos) << error;
}

TEST(HostileCsv, MoreRowsThanTheLimitAreRefusedBeforeAnyIsParsed) {
  std::string text = "time_s,pdet_cmh2o,infused_ml\n";
  for (int i = 0; i < 1001; ++i) text += std::to_string(i) + ",1,1\n";
  vc::CsvOptions options;
  options.max_rows = 1000;
  const std::string error = error_of(write_file("csv-rows", text), options);
  EXPECT_NE(error.find("more than 1000 data rows"), std::string::npos) << error;
}

// The rows are counted before parsing: comments, blank lines and lines of separators alone
// are not rows, so a table at the limit with them is read.
TEST(HostileCsv, CommentsAndBlankLinesDoNotCountAsRows) {
  std::string text = "# recorded in cmH2O\n\n  # a note after blanks\ntime_s,pdet_cmh2o,infused_ml\n";
  for (int i = 0; i < 1000; ++i) {
    text += std::to_string(i) + ",1,1\n";
    if (i % 100 == 0) text += "# marker\n\n , ,\n";
  }
  vc::CsvOptions options;
  options.max_rows = 1000;
  const vc::CsvTable table = vc::read_csv_table(write_file("csv-rows-at-limit", text), options);
  EXPECT_EQ(table.row_count(), 1000u);
}

TEST(HostileCsv, ABinaryFileIsRefusedInOneLine) {
  std::string bytes(200000, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 7919) % 251);
  const std::string error = error_of(write_file("csv-binary", bytes));
  EXPECT_LE(error.size(), vesica::kMaxErrorLine);
  EXPECT_EQ(error.find('\n'), std::string::npos);
}
