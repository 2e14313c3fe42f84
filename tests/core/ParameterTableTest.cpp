// A stage's parameter table: defaults come from the settings struct, every value given as
// text is checked (finite, in range, whole, one of the choices) and refused with a message
// naming what is accepted, the command line built from it says the same, and an unknown
// option gets a suggestion.
#include "vesica/core/ParameterTable.h"

#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include "vesica/core/ParameterCli.h"
#include "vesica/core/StageMain.h"
#include "vesica/core/Suggest.h"

namespace vesica {
namespace {

// A small stage's settings, with the defaults its library would give them.
struct ToySettings {
  double edge_mm = 4.0;
  double tet_size_mm = 0.0;  // 0 = automatic
  int iterations = 5;
  bool fluid = false;
  bool rescale = true;
  std::string unit = "cmh2o";
  std::string columns;
  std::string measured;
  double k_kpa = 0.0;  // 0 = automatic (the word "auto")
};

ParameterTable toy_table(ToySettings& s) {
  ParameterTable t("toy");
  t.number("edge_mm", s.edge_mm, "mm", NumberRange::at_least(0.5).at_most(50), "edge length");
  t.number("tet_size_mm", s.tet_size_mm, "mm",
           NumberRange::at_least(1).at_most(50).or_value(0, "auto").because("finer is too many"),
           "largest tetrahedron");
  t.integer("iterations", s.iterations, "-", NumberRange::at_least(1).at_most(50), "rounds");
  t.flag("fluid", s.fluid, "mesh the urine");
  t.flag_off("no_rescale", s.rescale, "keep the volume");
  t.choice("unit", s.unit, {"cmh2o", "kpa"}, "pressure unit");
  t.text("columns", s.columns, "KEY=NAME,...", "column names");
  t.input("measured", s.measured, "recording");
  t.number_or_word("k_kpa", s.k_kpa, 0.0, "kPa",
                   NumberRange::at_least(0.1).at_most(1e6).or_word("auto", "1000 mu"), "bulk");
  return t;
}

std::string refusal(ParameterTable& t, const std::string& name, const std::string& text) {
  for (Parameter& p : t.entries())
    if (p.name == name) try {
        p.assign(text);
        return "";
      } catch (const ParameterValueError& e) {
        return e.what();
      }
  return "no such entry";
}

TEST(ParameterTable, DefaultsAreTheSettingsStructsInitialisers) {
  ToySettings s;
  const ParameterTable t = toy_table(s);
  const nlohmann::json values = t.values();
  EXPECT_EQ(values["edge_mm"], 4.0);
  EXPECT_EQ(values["tet_size_mm"], 0.0);
  EXPECT_EQ(values["iterations"], 5);
  EXPECT_EQ(values["fluid"], false);
  EXPECT_EQ(values["no_rescale"], false);
  EXPECT_EQ(values["unit"], "cmh2o");
  EXPECT_EQ(t.find("edge_mm")->default_text(), "4 mm");
  EXPECT_EQ(t.find("tet_size_mm")->default_text(), "0");  // its meaning is in the range
}

TEST(ParameterTable, ValuesListEveryParameterButNotInputs) {
  ToySettings s;
  const ParameterTable t = toy_table(s);
  EXPECT_EQ(t.values().size(), t.entries().size() - 1);
  EXPECT_FALSE(t.values().contains("measured"));
  EXPECT_EQ(t.describe()["inputs"][0]["name"], "measured");
}

TEST(ParameterTable, GivenValuesReachTheBoundFields) {
  ToySettings s;
  ParameterTable t = toy_table(s);
  EXPECT_EQ(refusal(t, "edge_mm", "6.5"), "");
  EXPECT_EQ(refusal(t, "tet_size_mm", "0"), "");  // the special value
  EXPECT_EQ(refusal(t, "iterations", "12"), "");
  EXPECT_EQ(refusal(t, "fluid", "true"), "");
  EXPECT_EQ(refusal(t, "no_rescale", "true"), "");
  EXPECT_EQ(refusal(t, "unit", "kpa"), "");
  EXPECT_DOUBLE_EQ(s.edge_mm, 6.5);
  EXPECT_EQ(s.iterations, 12);
  EXPECT_TRUE(s.fluid);
  EXPECT_FALSE(s.rescale);  // the "no_" flag turns the setting off
  EXPECT_EQ(s.unit, "kpa");
  EXPECT_EQ(t.values()["no_rescale"], true);
}

TEST(ParameterTable, ValuesOutsideTheRangeAreRefusedWithTheRangeAndWhy) {
  ToySettings s;
  ParameterTable t = toy_table(s);
  EXPECT_EQ(refusal(t, "tet_size_mm", "0.001"),
            "0.001 is outside 0 (auto) or [1, 50] mm: finer is too many");
  EXPECT_EQ(refusal(t, "edge_mm", "1e30"), "1e30 is outside [0.5, 50] mm");
  EXPECT_EQ(refusal(t, "iterations", "0"), "0 is outside [1, 50]");
  EXPECT_DOUBLE_EQ(s.tet_size_mm, 0.0);  // nothing stored
  EXPECT_DOUBLE_EQ(s.edge_mm, 4.0);
}

TEST(ParameterTable, TextThatIsNotExactlyANumberIsRefused) {
  ToySettings s;
  ParameterTable t = toy_table(s);
  EXPECT_EQ(refusal(t, "edge_mm", "4mm"), "'4mm' is not a number");
  EXPECT_EQ(refusal(t, "edge_mm", "nan"), "'nan' is not a finite number");
  EXPECT_EQ(refusal(t, "edge_mm", "inf"), "'inf' is not a finite number");
  EXPECT_EQ(refusal(t, "edge_mm", "1e999"), "'1e999' is too large for a number");
  EXPECT_EQ(refusal(t, "edge_mm", ""), "'' is not a number");
  EXPECT_EQ(refusal(t, "iterations", "3.5"), "'3.5' is not a whole number");
  EXPECT_EQ(refusal(t, "unit", "mmhg"), "'mmhg' is not one of cmh2o, kpa");
  EXPECT_EQ(refusal(t, "fluid", "yes"), "'yes' is not true or false");
}

TEST(ParameterTable, DescriptionCarriesUnitRangeAndDefault) {
  ToySettings s;
  const nlohmann::json d = toy_table(s).describe();
  EXPECT_EQ(d["tool"], "toy");
  const nlohmann::json& tet = d["parameters"][1];
  EXPECT_EQ(tet["name"], "tet_size_mm");
  EXPECT_EQ(tet["option"], "--tet-size-mm");
  EXPECT_EQ(tet["unit"], "mm");
  EXPECT_EQ(tet["default"], 0.0);
  EXPECT_EQ(tet["range"]["min"], 1.0);
  EXPECT_EQ(tet["range"]["max"], 50.0);
  EXPECT_EQ(tet["range"]["special"][0]["meaning"], "auto");
  EXPECT_EQ(d["parameters"][5]["choices"], nlohmann::json({"cmh2o", "kpa"}));
}

TEST(ParameterTable, AWordStandsForTheFieldsSpecialValueAndItsNumberIsRefused) {
  ToySettings s;
  ParameterTable t = toy_table(s);
  EXPECT_EQ(t.values()["k_kpa"], "auto");
  EXPECT_EQ(t.find("k_kpa")->default_text(), "auto");  // not "auto kPa"
  EXPECT_EQ(t.find("k_kpa")->accepted(), "auto (1000 mu) or [0.1, 1000000] kPa");
  EXPECT_EQ(refusal(t, "k_kpa", "0"), "0 is outside auto (1000 mu) or [0.1, 1000000] kPa");
  EXPECT_EQ(refusal(t, "k_kpa", "50"), "");
  EXPECT_DOUBLE_EQ(s.k_kpa, 50.0);
  EXPECT_EQ(refusal(t, "k_kpa", "auto"), "");
  EXPECT_DOUBLE_EQ(s.k_kpa, 0.0);
}

TEST(ParameterTable, NamingAnEntryTwiceIsAProgrammingError) {
  double x = 0, y = 0;
  ParameterTable t("toy");
  t.number("x", x, "-", NumberRange::at_least(0).at_most(1), "x");
  EXPECT_THROW(t.number("x", y, "-", NumberRange::at_least(0).at_most(1), "again"),
               std::logic_error);
}

TEST(ParameterTable, TableWithDefaultsOwnsItsSettings) {
  ParameterTable t = table_with_defaults(toy_table);
  EXPECT_EQ(refusal(t, "edge_mm", "8"), "");
  EXPECT_EQ(t.values()["edge_mm"], 8.0);
  EXPECT_EQ(table_with_defaults(toy_table).values()["edge_mm"], 4.0);  // a fresh copy
}

// ---- the command line made from a table ----

struct Parsed {
  int code = -1;
  std::string err, out;
};

Parsed run_toy(std::vector<std::string> args, ToySettings& s) {
  CLI::App app("toy stage", "vesica-toy");
  CommonOptions common;
  ParameterTable table = toy_table(s);
  add_parameter_options(app, table);
  add_common_options(app, common);
  args.insert(args.begin(), "vesica-toy");
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  Parsed r;
  r.code =
      run_stage_main(app, static_cast<int>(argv.size()), argv.data(), common, [] { return 0; });
  r.out = testing::internal::GetCapturedStdout();
  r.err = testing::internal::GetCapturedStderr();
  return r;
}

TEST(ParameterCli, OptionsStoreIntoTheSettings) {
  ToySettings s;
  const Parsed r = run_toy(
      {"--edge-mm", "2.5", "--fluid", "--no-rescale", "--unit", "kpa", "--measured", "m.csv"}, s);
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_DOUBLE_EQ(s.edge_mm, 2.5);
  EXPECT_TRUE(s.fluid);
  EXPECT_FALSE(s.rescale);
  EXPECT_EQ(s.unit, "kpa");
  EXPECT_EQ(s.measured, "m.csv");
}

TEST(ParameterCli, OutOfRangeIsAUsageErrorNamingOptionValueAndRange) {
  ToySettings s;
  const Parsed r = run_toy({"--tet-size-mm", "0.001"}, s);
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err,
            "vesica-toy: usage error: --tet-size-mm 0.001 is outside 0 (auto) or [1, 50] mm: "
            "finer is too many (see vesica-toy --help)\n");
}

TEST(ParameterCli, UnknownOptionGetsASuggestion) {
  ToySettings s;
  const Parsed r = run_toy({"--edge", "3", "--itrations", "4"}, s);
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("unknown option --edge (did you mean --edge-mm?); unknown option "
                       "--itrations (did you mean --iterations?)"),
            std::string::npos)
      << r.err;
}

TEST(ParameterCli, HelpShowsUnitRangeAndDefault) {
  ToySettings s;
  const Parsed r = run_toy({"--help"}, s);
  EXPECT_EQ(r.code, 0);
  EXPECT_NE(r.out.find("edge length (accepts [0.5, 50] mm; default 4 mm)"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("largest tetrahedron (accepts 0 (auto) or [1, 50] mm; default 0)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("mesh the urine (default off)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("--parameters-json"), std::string::npos) << r.out;  // hidden
}

TEST(ParameterCli, ParametersJsonDescribesTheTable) {
  ToySettings s;
  const Parsed r = run_toy({"--parameters-json"}, s);
  EXPECT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_EQ(d["tool"], "toy");
  EXPECT_EQ(d["parameters"].size(), 8u);
}

TEST(Suggest, AWordCutShortBeforeItsUnitFindsTheKey) {
  EXPECT_EQ(closest_match("mu", {"mu_kpa", "k_kpa", "k1_kpa"}), "mu_kpa");
  EXPECT_EQ(closest_match("mu-kp", {"mu-kpa", "k-kpa"}), "mu-kpa");
  EXPECT_EQ(closest_match("edge_mmm", {"edge_mm", "max_hole_mm"}), "edge_mm");
  EXPECT_EQ(closest_match("thickness", {"thickness_mm", "thickness_by_region"}), "thickness_mm");
  EXPECT_EQ(closest_match("zzz", {"mu_kpa"}), "");
}

}  // namespace
}  // namespace vesica
