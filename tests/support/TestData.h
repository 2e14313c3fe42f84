#pragma once
// Where tests find the shared real data (../shared beside the checkout) and the built
// executables. A test that needs ../shared fails, not skips, when CI=true.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace vesica::test {

inline std::filesystem::path shared_dir() {
  const char* env = std::getenv("VESICA_SHARED_DIR");
  return env ? std::filesystem::path(env) : std::filesystem::path("../shared");
}

inline std::filesystem::path bin_dir() {
  const char* env = std::getenv("VESICA_BIN_DIR");
  return env ? std::filesystem::path(env) : std::filesystem::current_path();
}

inline std::filesystem::path source_dir() {
  const char* env = std::getenv("VESICA_SOURCE_DIR");
  return env ? std::filesystem::path(env) : std::filesystem::current_path();
}

inline bool running_in_ci() {
  const char* ci = std::getenv("CI");
  return ci && std::string(ci) == "true";
}

// A fresh empty folder for one test, removed by the next run of the same test. It lives in
// the build tree (beside bin/), so that two checkouts testing at once never share one.
inline std::filesystem::path scratch_dir(const std::string& name) {
  const char* bin = std::getenv("VESICA_BIN_DIR");
  const std::filesystem::path root =
      bin ? std::filesystem::path(bin).parent_path() / "test-scratch"
          : std::filesystem::temp_directory_path() / "vesica-test-scratch";
  auto dir = root / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A folder in the build tree for what a test leaves to be looked at afterwards
// (screenshots, printed reports): build/test-artefacts/<name>, emptied at the start.
inline std::filesystem::path artefact_dir(const std::string& name) {
  auto dir = bin_dir().parent_path() / "test-artefacts" / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A file's whole content ("" when it cannot be read).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace vesica::test

// Use at the top of a test body: the path of a file in ../shared, or skip (locally)
// / fail (CI=true) when it is missing.
#define VESICA_REQUIRE_SHARED(var, relative)                                       \
  const std::filesystem::path var = ::vesica::test::shared_dir() / (relative);     \
  if (!std::filesystem::exists(var)) {                                             \
    if (::vesica::test::running_in_ci()) FAIL() << "missing shared data: " << var; \
    GTEST_SKIP() << "shared data not found: " << var;                              \
  }
