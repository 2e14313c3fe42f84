#pragma once
// history.csv of vesica-simulate (level 1 or 2) read back for the end-to-end tests.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vesica::test {

struct HistoryCsvRow {
  double t, infused, volume, pves, pabd, pdet, flow, voided;  // s, ml, cmH2O, ml/s
};

// The rows after the header; the comment lines before it ("# ... voided by ...") skipped.
inline std::vector<HistoryCsvRow> read_history(const std::filesystem::path& csv) {
  std::ifstream in(csv);
  std::string line;
  while (std::getline(in, line) && !line.empty() && line[0] == '#') {
  }
  EXPECT_EQ(line,
            "time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,flow_ml_s,voided_ml");
  std::vector<HistoryCsvRow> rows;
  while (std::getline(in, line)) {
    HistoryCsvRow r{};
    char c;
    std::istringstream s(line);
    s >> r.t >> c >> r.infused >> c >> r.volume >> c >> r.pves >> c >> r.pabd >> c >> r.pdet >> c >>
        r.flow >> c >> r.voided;
    rows.push_back(r);
  }
  return rows;
}

}  // namespace vesica::test
