// The pipeline file: what `vesica validate` reports (line:column, suggestions, cycles)
// and the exact command lines a file turns into.
#include <gtest/gtest.h>

#include <algorithm>

#include "PipelineTestSupport.h"
#include "vesica/pipelines/Plan.h"

namespace fs = std::filesystem;
using namespace vesica::test;
using vesica::pipelines::build_plan;
using vesica::pipelines::Diagnostics;
using vesica::pipelines::parse_pipeline_text;

namespace {

CommandResult validate(const std::string& name, const std::string& yaml) {
  const fs::path dir = scratch_dir("validate-" + name);
  write_text(dir / "pipe.yaml", yaml);
  return run_vesica("validate " + quoted((dir / "pipe.yaml").string()), dir);
}

vesica::pipelines::Plan plan_of(const fs::path& file, const std::string& yaml, Diagnostics& d) {
  write_text(file, yaml);
  return build_plan(parse_pipeline_text(yaml, file, d), {{}, bin_dir()}, d);
}

}  // namespace

TEST(PipelineFile, MalformedYamlNamesTheLine) {
  // Line 4 opens a flow map that is never closed.
  const auto r = validate("malformed",
                          "pipeline: p\n"
                          "stages:\n"
                          "  a: {tool: teststage, output: a.txt}\n"
                          "  b: {tool: teststage, input: a.txt, output: b.txt\n"
                          "  c: {tool: teststage, output: c.txt}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("malformed YAML"), std::string::npos) << r.err;
  // yaml-cpp notices the unclosed map at the start of line 5 at the latest.
  const bool names_line = r.err.find("pipe.yaml:4:") != std::string::npos ||
                          r.err.find("pipe.yaml:5:") != std::string::npos;
  EXPECT_TRUE(names_line) << r.err;
}

TEST(PipelineFile, UnknownKeyGetsSuggestionWithPosition) {
  const auto r = validate("unknown-key",
                          "pipeline: p\n"
                          "stages:\n"
                          "  a:\n"
                          "    tool: teststage\n"
                          "    ouptut: a.txt\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:5:5: unknown stage key 'ouptut' (did you mean 'output'?)"),
            std::string::npos)
      << r.err;
}

TEST(PipelineFile, UnknownTopLevelKeyAndToolAreSuggested) {
  const auto r = validate("unknown-top",
                          "pipeline: p\n"
                          "stagez: {}\n"
                          "stages:\n"
                          "  surface: {tool: surfce, output: s.vtp}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:2:1: unknown top-level key 'stagez' (did you mean 'stages'?)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:4:19: unknown tool 'surfce'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("did you mean 'surface'?"), std::string::npos) << r.err;
}

TEST(PipelineFile, WrongTypesAreReported) {
  const auto r = validate("wrong-type",
                          "stages:\n"
                          "  a:\n"
                          "    tool: teststage\n"
                          "    output: a.txt\n"
                          "    params: [1, 2]\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:5:13: 'a.params' must be a map, found a list"), std::string::npos)
      << r.err;
}

TEST(PipelineFile, CycleIsDetected) {
  const auto r = validate("cycle",
                          "stages:\n"
                          "  a: {tool: teststage, input: c.txt, output: a.txt}\n"
                          "  b: {tool: teststage, input: a.txt, output: b.txt}\n"
                          "  c: {tool: teststage, input: b.txt, output: c.txt}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("stages form a cycle: a -> c -> b -> a"), std::string::npos) << r.err;
}

TEST(PipelineFile, DuplicateOutputsAndMissingInputsAreReported) {
  const auto r = validate("duplicates",
                          "inputs: {ct: does/not/exist}\n"
                          "stages:\n"
                          "  a: {tool: teststage, input: '${inputs.ct}', output: x.txt}\n"
                          "  b: {tool: teststage, output: x.txt}\n"
                          "  c: {tool: teststage, input: nowhere.txt, output: c.txt}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:1:14: external input 'ct' not found"), std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:4:32: output 'x.txt' of stage 'b' collides with 'x.txt' of "
                       "stage 'a' (line 3)"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:5:31: input 'nowhere.txt' of stage 'c' is not written"),
            std::string::npos)
      << r.err;
}

TEST(PipelineFile, ValidFileIsOk) {
  const auto r = validate("valid",
                          "stages:\n"
                          "  a: {tool: teststage, output: a.txt}\n"
                          "  b: {tool: teststage, input: a.txt, output: b.txt}\n");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ok (2 stages)"), std::string::npos);
}

TEST(PipelineFile, ParamsBecomeTheContractsCommandLine) {
  const fs::path dir = scratch_dir("argv");
  fs::create_directories(dir / "data" / "ct");
  Diagnostics d;
  const auto plan = plan_of(dir / "study" / "pipe.yaml",
                            "workdir: out\n"
                            "inputs: {ct: ../data/ct}\n"
                            "stages:\n"
                            "  segment:\n"
                            "    tool: teststage\n"  // no table: any param reaches the argv
                            "    input: ${inputs.ct}\n"
                            "    output: seg/bladder.nii.gz\n"
                            "    params: {seed: auto, lower_hu: -20, fluid: true, no_void: false,"
                            " seed_point: [1, 2.5, 3], label: 'true'}\n"
                            "  surface:\n"
                            "    tool: teststage\n"
                            "    input: seg/bladder.nii.gz\n"
                            "    inputs: {aux: '${inputs.ct}'}\n"
                            "    output: bladder.vtp\n"
                            "    report: reports/surface.json\n",
                            d);
  ASSERT_TRUE(d.empty()) << d.format("pipe.yaml");
  ASSERT_EQ(plan.stages.size(), 2u);
  // Hand-written expectation: workdir study/out, so the CT folder is ../../data/ct.
  const std::vector<std::string> segment = {"../../data/ct",
                                            "-o",
                                            "seg/bladder.nii.gz",
                                            "--seed",
                                            "auto",
                                            "--lower-hu",
                                            "-20",
                                            "--fluid",
                                            "--seed-point",
                                            "1,2.5,3",
                                            "--label",
                                            "true",
                                            "--report",
                                            ".vesica/segment.json",
                                            "--manifest",
                                            ".vesica/segment.manifest.json"};
  EXPECT_EQ(plan.stages[0].argv, segment);
  const std::vector<std::string> surface = {"seg/bladder.nii.gz",
                                            "-o",
                                            "bladder.vtp",
                                            "--aux",
                                            "../../data/ct",
                                            "--report",
                                            "reports/surface.json",
                                            "--manifest",
                                            ".vesica/surface.manifest.json"};
  EXPECT_EQ(plan.stages[1].argv, surface);
  EXPECT_EQ(plan.stages[1].deps, std::vector<std::size_t>{0});
  EXPECT_EQ(plan.workdir, (dir / "study" / "out").lexically_normal());
}

TEST(PipelineFile, DemoPipelineChainsTheStagesByTheirContracts) {
  const fs::path file = source_dir() / "pipelines" / "demo.yaml";
  Diagnostics d;
  const auto plan = build_plan(vesica::pipelines::load_pipeline_file(file, d),
                               {scratch_dir("demo-plan"), bin_dir()}, d);
  ASSERT_TRUE(d.empty()) << d.format(file.string());
  std::vector<std::string> ids;
  for (const auto& s : plan.stages) ids.push_back(s.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"phantom", "segment", "surface", "mesh", "simulate",
                                           "compare"}));
  // Each stage depends on the one before it, found through the paths alone; compare reads
  // the simulation's history.
  for (std::size_t i = 1; i < 5; ++i)
    EXPECT_EQ(plan.stages[i].deps, std::vector<std::size_t>{i - 1}) << ids[i];
  EXPECT_EQ(plan.stages[5].deps, std::vector<std::size_t>{4});
  const auto& compare = plan.stages.back().argv;
  const auto measured = std::find(compare.begin(), compare.end(), "--measured");
  ASSERT_NE(measured, compare.end());
  EXPECT_TRUE(fs::exists(plan.in_workdir(*(measured + 1))));
  EXPECT_EQ(plan.stages[0].argv[0], "-o");  // the phantom has no input
}
