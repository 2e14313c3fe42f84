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
  expect_every_entry("surface", manifest_parameters(dir / ".vesica/s.vtp.manifest.json"),
                     {{"shape", "sphere"}, {"volume_ml", 20.0}, {"edge_mm", 5.0}});

  const auto mesh = run_command(
      tool_command("mesh", quoted((dir / "s.vtp").string()) + " -o " +
                               quoted((dir / "m.msh").string()) +
                               " --fluid --tet-size-mm 4 --thickness-by-region fixed=4.5"),
      dir);
  ASSERT_EQ(mesh.exit_code, 0) << mesh.err;
  expect_every_entry(
      "mesh", manifest_parameters(dir / ".vesica/m.msh.manifest.json"),
      {{"fluid", true}, {"tet_size_mm", 4.0}, {"thickness_by_region", {{"fixed", 4.5}}}});

  const auto simulate = run_command(
      tool_command("simulate", quoted((dir / "m.vtu").string()) + " -o " +
                                   quoted((dir / "sim").string()) +
                                   " --residual-ml 20 --start-ml 20 --capacity-ml 25 --no-void "
                                   "--no-series"),
      dir);
  ASSERT_EQ(simulate.exit_code, 0) << simulate.err;
  expect_every_entry("simulate", manifest_parameters(dir / ".vesica/sim.manifest.json"),
                     {{"residual_ml", 20.0},
                      {"start_ml", 20.0},
                      {"capacity_ml", 25.0},
                      {"no_void", true},
                      {"no_series", true}});

  const auto compare = run_command(
      tool_command("compare",
                   "--measured " +
                       quoted((source_dir() / "pipelines/data/normal-female-34y.csv").string()) +
                       " -o " + quoted((dir / "report").string()) + " --spike-cmh2o 8"),
      dir);
  ASSERT_EQ(compare.exit_code, 0) << compare.err;
  expect_every_entry("compare", manifest_parameters(dir / ".vesica/report.manifest.json"),
                     {{"spike_cmh2o", 8.0}});
}

TEST(StageParameters, PhantomAndSegmentManifestsListEveryTableEntryAndNoUid) {
  // A small CT (3 mm voxels, 67 x 67 x 50): made and segmented in seconds.
  const fs::path dir = scratch_dir("stage-parameters-segment");
  const std::string ct = quoted((dir / "ct").string()), label = quoted((dir / "b.nii.gz").string());
  const auto phantom = run_command(
      tool_command("phantom", "-o " + ct +
                                  " --bladder-ml 200 --spacing-mm 3 --fov-mm 200,200,150 "
                                  "--noise-hu 10 --rng-seed 7"),
      dir);
  ASSERT_EQ(phantom.exit_code, 0) << phantom.err;
  expect_every_entry("phantom", manifest_parameters(dir / ".vesica/ct.manifest.json"),
                     {{"bladder_ml", 200.0},
                      {"spacing_mm", 3.0},
                      {"fov_mm", {200.0, 200.0, 150.0}},
                      {"noise_hu", 10.0},
                      {"rng_seed", 7}});

  const auto segment = run_command(
      tool_command("segment", ct + " -o " + label +
                                  " --seed 0,-15,-10 --min-volume-ml 20 --shell-outer-mm 10 "
                                  "--bias-levels 2"),
      dir);
  ASSERT_EQ(segment.exit_code, 0) << segment.err;
  const nlohmann::json parameters = manifest_parameters(dir / ".vesica/b.nii.gz.manifest.json");
  expect_every_entry("segment", parameters,
                     {{"seed", {0.0, -15.0, -10.0}},
                      {"min_volume_ml", 20.0},
                      {"shell_outer_mm", 10.0},
                      {"bias_levels", 2}});
  // The series is chosen by --series, not a parameter: neither its key nor a UID is one
  // (SeriesUid.* in tests/segment checks the whole manifest for the UID).
  EXPECT_FALSE(parameters.contains("series"));
}

TEST(StageParameters, SegmentAndPhantomParamsAreCheckedBeforeAnyStageRuns) {
  const fs::path dir = scratch_dir("stage-parameters-validate-segment");
  write_text(dir / "pipe.yaml",
             "stages:\n"
             "  phantom: {output: ct, params: {spacing_mm: 0.1, shape: ball}}\n"
             "  segment:\n"
             "    input: ct\n"
             "    output: b.nii.gz\n"
             "    params: {seed: autoo, lower_huu: -20, shell_outer_mm: 0}\n");
  const auto r = run_vesica("validate " + quoted((dir / "pipe.yaml").string()), dir);
  EXPECT_EQ(r.exit_code, 2);
  // Columns counted by hand in the YAML above.
  for (const char* expected :
       {"pipe.yaml:2:46: parameter 'spacing_mm' of phantom: 0.1 is outside [0.2, 10] mm\n",
        "pipe.yaml:2:58: parameter 'shape' of phantom: 'ball' is not one of sphere, ellipsoid, "
        "pouch\n",
        "pipe.yaml:6:20: parameter 'seed' of segment: 'autoo' is not x,y,z (LPS mm) or auto (did "
        "you mean 'auto'?)\n",
        "pipe.yaml:6:27: unknown parameter 'lower_huu' for segment (did you mean 'lower_hu'?)\n",
        "pipe.yaml:6:59: parameter 'shell_outer_mm' of segment: 0 is outside auto (the "
        "modality's: CT 9, MR 3) or (0, 100] mm\n"})
    EXPECT_NE(r.err.find(expected), std::string::npos) << expected << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 5) << r.err;

  // Their params are checked, so validate no longer names them as unchecked.
  write_text(dir / "good.yaml",
             "stages:\n"
             "  phantom: {output: ct, params: {spacing_mm: 3, fov_mm: [200, 200, 150]}}\n"
             "  segment: {input: ct, output: b.nii.gz, params: {seed: [0, -15, -10]}}\n");
  const auto good = run_vesica("validate " + quoted((dir / "good.yaml").string()), dir);
  EXPECT_EQ(good.exit_code, 0) << good.err;
  EXPECT_EQ(good.out.find("not checked"), std::string::npos) << good.out;
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
  const auto r = run_command(tool_command("simulate", "bladder.vtu -o sim --mu 3"), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown option --mu (did you mean --mu-kpa?)"), std::string::npos) << r.err;
  const auto s = run_command(tool_command("surface", "--shape sphere -o s.vtp --edge-mmm 4"), dir);
  EXPECT_EQ(s.exit_code, 2);
  EXPECT_NE(s.err.find("unknown option --edge-mmm (did you mean --edge-mm?)"), std::string::npos)
      << s.err;
}
