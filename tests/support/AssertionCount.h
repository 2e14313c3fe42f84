#pragma once
// Counts the GoogleTest assertions a test process executes, so that a change to how the
// tests are run (tiers, one ctest entry per case) can show that nothing stopped running:
// `make test` prints the sum over every process.
//
// Every test source gets this header first (vesica_test_support forces it in). It
// redefines the prefix that each EXPECT_*/ASSERT_* statement macro of GoogleTest expands
// to (EXPECT_EQ, EXPECT_NEAR, EXPECT_TRUE, EXPECT_THROW, EXPECT_NO_FATAL_FAILURE, death
// tests...): `switch (0) case 0: default:`, there only to silence a dangling-else warning.
// Here the switch's value is a call that adds one to the process's count and returns 0, so
// one executed assertion counts once, in a loop once per pass, and the statement's meaning
// is unchanged. Macros expanded inside GoogleTest's own headers (included above the
// redefinition) do not count; FAIL, SUCCEED and GTEST_SKIP are not assertions and do not.
//
// When VESICA_ASSERTION_LOG names a file, the process appends one line at exit:
// "<assertions> <command line>".
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#ifndef GTEST_AMBIGUOUS_ELSE_BLOCKER_
#error "GoogleTest no longer defines GTEST_AMBIGUOUS_ELSE_BLOCKER_: update AssertionCount.h"
#endif

namespace vesica::test {

inline std::atomic<long long> assertions_executed{0};

inline int count_assertion() {
  assertions_executed.fetch_add(1, std::memory_order_relaxed);
  return 0;
}

// The process's command line with spaces between the arguments. Read from /proc rather
// than from GoogleTest's flags, which may already be destroyed when the report is written.
inline std::string command_line() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (char& c : text)
    if (c == '\0') c = ' ';
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

// Written when the process ends normally (static destruction), one short line in one
// write, so that processes running at once append without mixing their lines.
struct AssertionCountReport {
  AssertionCountReport() = default;
  AssertionCountReport(const AssertionCountReport&) = delete;
  AssertionCountReport& operator=(const AssertionCountReport&) = delete;
  ~AssertionCountReport() {
    const char* path = std::getenv("VESICA_ASSERTION_LOG");
    if (!path || !*path) return;
    const std::string line =
        std::to_string(assertions_executed.load()) + " " + command_line() + "\n";
    if (std::FILE* f = std::fopen(path, "a")) {
      std::fwrite(line.data(), 1, line.size(), f);
      std::fclose(f);
    }
  }
};

inline AssertionCountReport assertion_count_report;

}  // namespace vesica::test

#undef GTEST_AMBIGUOUS_ELSE_BLOCKER_
#define GTEST_AMBIGUOUS_ELSE_BLOCKER_        \
  switch (::vesica::test::count_assertion()) \
  case 0:                                    \
  default:  // NOLINT
