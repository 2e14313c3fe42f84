#pragma once
// An independent reader for the round-trip tests: Debian's python3-meshio (Makefile
// DEPENDENCIES), run as /usr/bin/python3 so that a user's own Python does not stand in.
// The script prints JSON on its last line.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

namespace vesica::test {

inline nlohmann::json run_python(const std::string& script, const std::filesystem::path& dir) {
  const std::filesystem::path file = dir / "reader.py";
  std::ofstream(file) << script;
  const std::string command = "/usr/bin/python3 " + file.string() + " 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buffer{};
  while (pipe && fgets(buffer.data(), buffer.size(), pipe.get())) out += buffer.data();
  const auto last = out.find_last_of('\n', out.size() >= 2 ? out.size() - 2 : 0);
  const std::string line = last == std::string::npos ? out : out.substr(last + 1);
  const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
  if (j.is_discarded()) ADD_FAILURE() << "the Python reader failed:\n" << out;
  return j;
}

}  // namespace vesica::test
