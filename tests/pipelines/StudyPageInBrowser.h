#pragma once
// A study's outputs as its tests read them: study.csv as a table, and the page as headless
// Chromium shows it in a 1280-px window: the DOM after its scripts ran (PageCheckScript.h
// writes what it measured into <body data-...>) and the browser's log.
#include <cstdlib>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "PipelineTestSupport.h"

namespace vesica::test {

// study.csv as variant -> column -> cell (the study tests' cells hold no comma).
using StudyTable = std::map<std::string, std::map<std::string, std::string>>;
inline StudyTable read_study_table(const std::filesystem::path& csv) {
  std::istringstream in(slurp(csv));
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  std::stringstream hs(line);
  for (std::string cell; std::getline(hs, cell, ',');) header.push_back(cell);
  StudyTable table;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::map<std::string, std::string> row;
    std::size_t i = 0;
    for (std::string cell; i < header.size() && std::getline(ls, cell, ',');)
      row[header[i++]] = cell;
    table[row["variant"]] = row;
  }
  return table;
}

struct PageInBrowser {
  int exit_code = -1;
  std::string dom, log;
  // The value of <body data-NAME="...">, or "".
  std::string body(const std::string& name) const {
    std::smatch m;
    return std::regex_search(dom, m, std::regex("<body[^>]*\\sdata-" + name + "=\"([^\"]*)\""))
               ? m[1].str()
               : std::string();
  }
  // How often `text` occurs in the DOM.
  std::size_t count(const std::string& text) const {
    std::size_t n = 0;
    for (auto at = dom.find(text); at != std::string::npos; at = dom.find(text, at + 1)) ++n;
    return n;
  }
};

// The chromium command line of the study page tests, up to the window's height.
inline std::string chromium_1280(const std::filesystem::path& profile) {
  return "timeout 120 chromium --headless --no-sandbox --disable-gpu "
         "--disable-background-networking --disable-component-update --no-first-run "
         "--disable-dev-shm-usage --hide-scrollbars --virtual-time-budget=3000 "
         "--user-data-dir=" +
         quoted(profile.string()) + " --window-size=1280,";
}

// Loads `page` in a fresh profile under `scratch` and dumps its DOM.
inline PageInBrowser page_in_chromium(const std::filesystem::path& page,
                                      const std::filesystem::path& scratch) {
  const auto r = run_command(chromium_1280(scratch / "profile") +
                                 "900 --enable-logging=stderr --v=0 --dump-dom " +
                                 quoted("file://" + page.string()),
                             scratch);
  return {r.exit_code, r.out, r.out + r.err};
}

// chromium present, or the test fails in CI and is skipped elsewhere.
#define VESICA_REQUIRE_CHROMIUM()                                             \
  if (std::system("command -v chromium > /dev/null 2>&1") != 0) {             \
    if (vesica::test::running_in_ci()) FAIL() << "chromium is not installed"; \
    GTEST_SKIP() << "chromium is not installed";                              \
  }

// The page loaded without a script error or console error, and the page's own checks ran.
inline void expect_page_clean(const PageInBrowser& p) {
  ASSERT_EQ(p.exit_code, 0) << p.log;
  EXPECT_EQ(p.log.find("Uncaught"), std::string::npos) << p.log;
  EXPECT_FALSE(std::regex_search(p.log, std::regex("CONSOLE.*[Ee]rror"))) << p.log;
  EXPECT_NE(p.dom.find("<pre id=\"js-errors\" hidden=\"\"></pre>"), std::string::npos);
}

}  // namespace vesica::test
