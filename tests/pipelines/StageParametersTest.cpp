// The stage executables built from parameter tables, as a user and the runner meet them:
// each describes the very table `vesica validate` checks against, writes every entry into
// its manifest, shows units, ranges and defaults in --help, refuses a bad value in one line
// naming option, value and range, and suggests the option meant by an unknown one.
#include <gtest/gtest.h>

#include "PipelineTestSupport.h"
#include "vesica/pipelines/StageTables.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

std::string tool_command(const std::string& tool, const std::string& args) {
  return quoted((bin_dir() / ("vesica-" + tool)).string()) + " " + args;
}

nlohmann::json manifest_parameters(const fs::path& manifest) {
  return nlohmann::json::parse(slurp(manifest))["parameters"];
}

// Every entry of the tool's table is in the manifest, with its default unless `given`
// says otherwise.
void expect_every_entry(const std::string& tool, const nlohmann::json& parameters,
                        const nlohmann::json& given) {
  const nlohmann::json defaults = vesica::pipelines::stage_table(tool)->values();
  for (const auto& [key, value] : defaults.items()) {
    ASSERT_TRUE(parameters.contains(key)) << tool << ": manifest lacks " << key;
    EXPECT_EQ(parameters[key], given.contains(key) ? given[key] : value) << tool << ": " << key;
  }
}

// A 20 ml sphere with 5 mm edges: a few hundred triangles, made in well under a second.
fs::path small_sphere(const fs::path& dir) {
  const auto r =
      run_command(tool_command("surface", "--shape sphere --volume-ml 20 --edge-mm 5 -o " +
                                              quoted((dir / "s.vtp").string())),
                  dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return dir / "s.vtp";
}

}  // namespace

TEST(StageParameters, EachStageDescribesTheTableTheRunnerChecks) {
  const fs::path dir = scratch_dir("stage-parameters-json");
  for (const std::string& tool : vesica::pipelines::tools_with_tables()) {
    const auto r = run_command(tool_command(tool, "--parameters-json"), dir);
    ASSERT_EQ(r.exit_code, 0) << tool << ": " << r.err;
    EXPECT_EQ(nlohmann::json::parse(r.out), vesica::pipelines::stage_table(tool)->describe())
        << tool;
  }
}

TEST(StageParameters, ManifestsListEveryTableEntry) {
  const fs::path dir = scratch_dir("stage-parameters-manifest");
  small_sphere(dir);
  expect_every_entry("surface", manifest_parameters(dir / "s.vtp.manifest.json"),
                     {{"shape", "sphere"}, {"volume_ml", 20.0}, {"edge_mm", 5.0}});

  const auto mesh = run_command(
      tool_command("mesh", quoted((dir / "s.vtp").string()) + " -o " +
                               quoted((dir / "m.msh").string()) +
                               " --fluid --tet-size-mm 4 --thickness-by-region fixed=4.5"),
      dir);
  ASSERT_EQ(mesh.exit_code, 0) << mesh.err;
  expect_every_entry(
      "mesh", manifest_parameters(dir / "m.msh.manifest.json"),
      {{"fluid", true}, {"tet_size_mm", 4.0}, {"thickness_by_region", {{"fixed", 4.5}}}});

  const auto compare = run_command(
      tool_command("compare",
                   "--measured " +
                       quoted((source_dir() / "pipelines/data/normal-female-34y.csv").string()) +
                       " -o " + quoted((dir / "report").string()) + " --spike-cmh2o 8"),
      dir);
  ASSERT_EQ(compare.exit_code, 0) << compare.err;
  expect_every_entry("compare", manifest_parameters(dir / "report.manifest.json"),
                     {{"spike_cmh2o", 8.0}});
}

TEST(StageParameters, HelpShowsUnitsRangesAndDefaults) {
  const fs::path dir = scratch_dir("stage-parameters-help");
  const auto r = run_command(tool_command("mesh", "--help"), dir);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("--thickness-mm NUMBER       wall thickness (accepts [0.1, 30] mm; "
                       "default 3 mm)"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("largest tetrahedron edge (accepts 0 (the wall's mean edge length) or "
                       "[1, 50] mm; default 0)"),
            std::string::npos)
      << r.out;
}

TEST(StageParameters, OutOfRangeOptionIsOneUsageLineAndWritesNothing) {
  const fs::path dir = scratch_dir("stage-parameters-range");
  const fs::path surface = small_sphere(dir);
  const auto r = run_command(
      tool_command("mesh", quoted(surface.string()) + " -o " + quoted((dir / "m.msh").string()) +
                               " --fluid --tet-size-mm 0.001"),
      dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "vesica-mesh: usage error: --tet-size-mm 0.001 is outside 0 (the wall's mean edge "
            "length) or [1, 50] mm: finer than 1 mm, a 500 ml bladder needs over 4 million "
            "tetrahedra (see vesica-mesh --help)\n");
  EXPECT_FALSE(fs::exists(dir / "m.msh"));
}

TEST(StageParameters, TooManyTetrahedraAreRefusedBeforeMeshing) {
  // A 3 litre sphere with 1 mm tetrahedra: V / (a^3 / (6 sqrt 2)) = 3e6 / 0.1179 = 25 million.
  const fs::path dir = scratch_dir("stage-parameters-tets");
  const auto s = run_command(tool_command("surface",
                                          "--shape sphere --volume-ml 3000 "
                                          "--edge-mm 12 -o " +
                                              quoted((dir / "big.vtp").string())),
                             dir);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto r = run_command(
      tool_command("mesh", quoted((dir / "big.vtp").string()) + " -o " +
                               quoted((dir / "m.msh").string()) + " --fluid --tet-size-mm 1"),
      dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--tet-size-mm: tetrahedra of 1 mm would need over 25 million in this "
                       "3000 ml cavity (at most 5 million)"),
            std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir / "m.msh"));
}

TEST(StageParameters, UnknownOptionGetsTheOptionMeant) {
  const fs::path dir = scratch_dir("stage-parameters-unknown");
  // simulate has no table yet; the suggestion comes from the common stage frame.
  const auto r = run_command(tool_command("simulate", "bladder.vtu -o sim --mu 3"), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown option --mu (did you mean --mu-kpa?)"), std::string::npos) << r.err;
  const auto s = run_command(tool_command("surface", "--shape sphere -o s.vtp --edge-mmm 4"), dir);
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("unknown option --edge-mmm (did you mean --edge-mm?)"), std::string::npos)
      << s.err;
}
