#pragma once
// Helpers of the hostile-user tests (issue 37): the tools' paths, a scratch folder of one's
// own, and the one-line refusal every hostile case must end in.
#include <filesystem>
#include <fstream>
#include <string>

#include "MeasuredCommand.h"
#include "TestData.h"

namespace vesica::test {

inline std::string tool(const std::string& name) {
  return "'" + (bin_dir() / name).string() + "'";
}

inline std::filesystem::path fresh_dir(const std::string& name) {
  const std::filesystem::path dir = scratch_dir(name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The last line of `output`: "tool: error: ..." naming `what`, within 300 characters.
inline bool one_line_refusal(const std::string& output, const std::string& what) {
  std::string text = output;
  while (!text.empty() && text.back() == '\n') text.pop_back();
  const std::string line = text.substr(text.rfind('\n') + 1);
  return line.find("error") != std::string::npos && line.find(what) != std::string::npos &&
         line.size() <= 301;
}

// A refusal as issue 37 accepts it: exit 1 (2 for a usage error), one line naming `what`,
// within the deadline (no hang) and under 1 GB of memory.
#define EXPECT_REFUSED_IN_ONE_LINE(result, what)                                      \
  do {                                                                                \
    const auto& r_ = (result);                                                        \
    EXPECT_FALSE(r_.timed_out) << "no answer: " << r_.output;                         \
    EXPECT_TRUE(r_.exit_code == 1 || r_.exit_code == 2) << r_.exit_code << r_.output; \
    EXPECT_TRUE(::vesica::test::one_line_refusal(r_.output, what)) << r_.output;      \
    EXPECT_LT(r_.max_rss_mb, 1024) << r_.output;                                      \
  } while (false)

}  // namespace vesica::test
