// An error is one line a terminal shows whole, whatever the file quoted in it holds.
#include "vesica/core/Error.h"

#include <gtest/gtest.h>

TEST(Error, AFiveMegabyteCellBecomesOneShortLine) {
  const std::string cell(5 * 1024 * 1024, '7');
  const vesica::Error e("rec.csv", "row 2, column \"pves\": \"" + cell + "\" is not a number");
  const std::string line = e.what();
  EXPECT_LE(line.size(), vesica::kMaxErrorLine);
  EXPECT_EQ(line.rfind("rec.csv: row 2", 0), 0u);
  EXPECT_EQ(line.substr(line.size() - 3), "...");
}

TEST(Error, LineBreaksInAMessageBecomeSpaces) {
  const vesica::Error e("a.vtp", "VTK said:\nline two\r\tand three");
  EXPECT_EQ(std::string(e.what()), "a.vtp: VTK said: line two  and three");
}

TEST(Error, ACutNeverSplitsAUtf8Character) {
  // 'é' is two bytes: a cut at an odd length must step back to a character boundary.
  std::string text;
  for (int i = 0; i < 400; ++i) text += "\xC3\xA9";
  const std::string line = vesica::single_line(text, 100);
  EXPECT_LE(line.size(), 100u);
  EXPECT_EQ((line.size() - 3) % 2, 0u);
}
