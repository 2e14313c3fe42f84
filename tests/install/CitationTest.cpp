// The licence and citation a user or a journal reads: CITATION.cff carries what the Citation
// File Format 1.2.0 requires (cff-version, message, title, authors) and agrees with the
// program (the version vesica --version prints) and with LICENSE (the GPL version 3 text,
// SPDX GPL-3.0-or-later, the licence the README explains).
#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>
#include <string>

#include "TestData.h"
#include "vesica/core/Version.h"

namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Citation, CarriesTheFieldsTheFormatRequires) {
  const YAML::Node cff = YAML::LoadFile((vesica::test::source_dir() / "CITATION.cff").string());
  EXPECT_EQ(cff["cff-version"].as<std::string>(), "1.2.0");
  for (const char* key : {"message", "title"})
    EXPECT_FALSE(cff[key].as<std::string>("").empty()) << key;
  ASSERT_TRUE(cff["authors"].IsSequence());
  ASSERT_GT(cff["authors"].size(), 0u);
  for (const auto& author : cff["authors"])  // a person (family-names) or an entity (name)
    EXPECT_TRUE(author["family-names"] || author["name"]);
}

TEST(Citation, NamesTheVersionTheProgramReports) {
  const YAML::Node cff = YAML::LoadFile((vesica::test::source_dir() / "CITATION.cff").string());
  EXPECT_EQ(cff["version"].as<std::string>(), vesica::kVersion);
}

TEST(Citation, LicenceIsTheGplVersion3OrLaterOfLicenseAndReadme) {
  const YAML::Node cff = YAML::LoadFile((vesica::test::source_dir() / "CITATION.cff").string());
  EXPECT_EQ(cff["license"].as<std::string>(), "GPL-3.0-or-later");
  const std::string license = read_text(vesica::test::source_dir() / "LICENSE");
  EXPECT_EQ(license.find("GNU GENERAL PUBLIC LICENSE"), license.find_first_not_of(' '));
  EXPECT_NE(license.find("Version 3, 29 June 2007"), std::string::npos);
  const std::string readme = read_text(vesica::test::source_dir() / "README.md");
  EXPECT_NE(readme.find("GPL-3.0-or-later"), std::string::npos);
}

}  // namespace
