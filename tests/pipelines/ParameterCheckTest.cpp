// `vesica validate` (and `vesica run`, which validates first) checks every stage's params,
// named inputs and study values against the stage's parameter table before any stage
// runs: FILE:LINE:COL, a suggestion for a misspelt key, what is accepted for a bad value.
// The expected positions are counted by hand in the YAML written here.
#include <gtest/gtest.h>

#include "PipelineTestSupport.h"
#include "vesica/pipelines/ParameterReference.h"
#include "vesica/pipelines/StageTables.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

CommandResult validate_yaml(const std::string& name, const std::string& yaml) {
  const fs::path dir = scratch_dir("params-" + name);
  write_text(dir / "pipe.yaml", yaml);
  return run_vesica("validate " + quoted((dir / "pipe.yaml").string()), dir);
}

}  // namespace

TEST(ParameterCheck, MisspeltParameterIsNamedAtItsKeyWithASuggestion) {
  const auto r = validate_yaml("misspelt",
                               "pipeline: p\n"
                               "stages:\n"
                               "  surface:\n"
                               "    output: s.vtp\n"
                               "    params: {shape: sphere, edge_mmm: 4}\n");
  EXPECT_EQ(r.exit_code, 2);
  const std::string expected =
      "pipe.yaml:5:29: unknown parameter 'edge_mmm' for surface (did you mean 'edge_mm'?)\n";
  ASSERT_GE(r.err.size(), expected.size()) << r.err;
  EXPECT_EQ(r.err.substr(r.err.size() - expected.size()), expected);  // one line, the only one
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST(ParameterCheck, OutOfRangeValueIsRefusedWithItsRangeBeforeAnyStageRuns) {
  const fs::path dir = scratch_dir("params-range-run");
  // a (a test stage) would run first; the mesh stage's value stops the whole run.
  write_text(dir / "pipe.yaml",
             "workdir: out\n"
             "stages:\n"
             "  a: {tool: teststage, output: a.txt}\n"
             "  mesh:\n"
             "    input: a.txt\n"
             "    output: m.msh\n"
             "    params: {fluid: true, tet_size_mm: 0.001}\n");
  const auto r = run_vesica("run " + quoted((dir / "pipe.yaml").string()), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:7:40: parameter 'tet_size_mm' of mesh: 0.001 is outside 0 "
                       "(the wall's mean edge length) or [1, 50] mm"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "out" / "a.txt"));  // nothing ran
}

TEST(ParameterCheck, ValuesOfTheWrongKindAreRefused) {
  const auto r = validate_yaml("kinds",
                               "stages:\n"
                               "  mesh:\n"
                               "    output: m.msh\n"
                               "    params: {fluid: 'yes', thickness_mm: true, grading: 0.3mm}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:4:21: parameter 'fluid' of mesh is a flag: write true or "
                       "false (unquoted), not 'yes'"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:4:42: parameter 'thickness_mm' of mesh takes a value ([0.1, "
                       "30] mm), not true"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:4:57: parameter 'grading' of mesh: '0.3mm' is not a number"),
            std::string::npos)
      << r.err;
}

TEST(ParameterCheck, StudyValuesAreCheckedOneByOne) {
  const auto r = validate_yaml("study",
                               "stages:\n"
                               "  surface: {output: s.vtp, params: {shape: pouch}}\n"
                               "  mesh: {input: s.vtp, output: m.msh}\n"
                               "study:\n"
                               "  matrix:\n"
                               "    surface.volume_ml: [100, 9000]\n"
                               "  variants:\n"
                               "    a: {mesh.gradng: 0.5}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:6:30: parameter 'volume_ml' of surface: 9000 is outside [1, "
                       "5000] ml"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:8:9: unknown parameter 'gradng' for mesh (did you mean "
                       "'grading'?)"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;  // 100 is fine
}

TEST(ParameterCheck, InputsAndParametersStayInTheirPlaces) {
  const auto r = validate_yaml("inputs",
                               "inputs: {cmg: pipe.yaml}\n"
                               "stages:\n"
                               "  compare:\n"
                               "    inputs: {measurd: '${inputs.cmg}'}\n"
                               "    output: report\n"
                               "    params: {simulated: x.csv}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:4:23: unknown input 'measurd' for compare (did you mean "
                       "'measured'?)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:6:14: 'simulated' is an input of compare: give it under "
                       "'inputs:', not 'params:'"),
            std::string::npos)
      << r.err;
}

TEST(ParameterCheck, ToolsWithoutATableAreNamedNotSilentlyPassed) {
  // Every shipped tool still without a table, and a tool of the tests' own.
  std::string yaml = "stages:\n  a: {tool: teststage, output: a.txt, params: {anything: 1}}\n";
  std::string named = "teststage";
  for (const auto& tool : vesica::pipelines::tools_without_tables()) {
    yaml += "  " + tool + ": {output: " + tool + ".out, params: {anything: 1}}\n";
    named += ", " + tool;
  }
  const auto r = validate_yaml("unchecked", yaml);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("; params of " + named + " not checked (no parameter table yet)"),
            std::string::npos)
      << r.out;
}

TEST(ParameterCheck, DemoAndStudyPipelinesPass) {
  for (const char* file : {"demo.yaml", "neobladder-whatif.yaml"}) {
    const fs::path dir = scratch_dir("params-shipped");
    const auto r = run_vesica("validate " + quoted((source_dir() / "pipelines" / file).string()) +
                                  " --workdir " + quoted(dir.string()),
                              dir);
    EXPECT_EQ(r.exit_code, 0) << file << ": " << r.err;
  }
}

TEST(ParameterReference, DocsListTheTablesDefaultsAndRanges) {
  const std::string docs = slurp(source_dir() / "docs" / "parameters.md");
  EXPECT_EQ(docs, vesica::pipelines::parameter_reference_markdown())
      << "docs/parameters.md differs from the parameter tables: regenerate it with\n"
         "  build/bin/vesica parameters > docs/parameters.md";
}
