// What `vesica validate` refuses before anything runs, each at its line: an output that
// would replace the workdir, the pipeline file, an external input, a stage's own input or
// vesica's own folder; a study larger than it says it may be; a key that is not a name.
// And a pipeline of many stages is checked whole (no check compares every stage with
// every other one, no recursion as deep as the chain).
#include <gtest/gtest.h>

#include "PipelineTestSupport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

CommandResult validate_in(const fs::path& dir, const std::string& yaml,
                          const std::string& name = "pipe.yaml") {
  write_text(dir / name, yaml);
  return run_vesica("validate " + quoted((dir / name).string()), dir);
}

}  // namespace

TEST(PipelineLimits, AnOutputThatIsTheWorkdirIsRefused) {
  const fs::path dir = scratch_dir("limits-dot");
  const auto r = validate_in(dir,
                             "stages:\n"
                             "  phantom: {tool: teststage, output: ., params: {label: P}}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:2:38: output '.' of stage 'phantom' is the workdir;"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find("collides"), std::string::npos) << r.err;  // said once, not per file
  EXPECT_EQ(run_vesica("run " + quoted((dir / "pipe.yaml").string()), dir).exit_code, 2);
  EXPECT_TRUE(fs::exists(dir / "pipe.yaml"));
}

TEST(PipelineLimits, AnOutputHoldingThePipelineFileOrAnExternalInputIsRefused) {
  const fs::path dir = scratch_dir("limits-holds");
  write_text(dir / "project/data/measured.csv", "1,2\n");
  const auto r = validate_in(dir / "project",
                             "workdir: ..\n"
                             "inputs: {cmg: data/measured.csv}\n"
                             "stages:\n"
                             "  a: {tool: teststage, output: project}\n"
                             "  b: {tool: teststage, output: project/data, inputs: {aux: "
                             "'${inputs.cmg}'}}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:4:32: output 'project' of stage 'a' holds the pipeline file "
                       "project/pipe.yaml;"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:5:32: output 'project/data' of stage 'b' holds the external "
                       "input 'cmg' (project/data/measured.csv);"),
            std::string::npos)
      << r.err;
}

TEST(PipelineLimits, AStageThatWouldReplaceItsOwnInputIsRefused) {
  const fs::path dir = scratch_dir("limits-own-input");
  write_text(dir / "b.vtp", "");
  const auto r = validate_in(dir,
                             "stages:\n"
                             "  surface: {tool: teststage, input: b.vtp, output: b.vtp}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:2:37: input 'b.vtp' of stage 'surface' is its own output "
                       "'b.vtp'"),
            std::string::npos)
      << r.err;
}

TEST(PipelineLimits, VesicasOwnFolderIsNoPlaceForAnOutput) {
  const fs::path dir = scratch_dir("limits-state");
  const auto r = validate_in(dir,
                             "stages:\n"
                             "  a: {tool: teststage, output: .vesica/a.txt}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:2:32: the output of stage 'a' may not be inside .vesica/"),
            std::string::npos)
      << r.err;
}

TEST(PipelineLimits, AKeyThatIsNotANameIsReportedAtItsLine) {
  const fs::path dir = scratch_dir("limits-key");
  const auto r = validate_in(dir,
                             "stages:\n"
                             "  a: {tool: teststage, output: a.txt}\n"
                             "  [b, c]: {tool: teststage, output: b.txt}\n"
                             "  d: {tool: teststage, output: d.txt, params: {{x: 1}: 2}}\n");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:3:3: a key must be a plain name, found a list"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("pipe.yaml:4:48: a key must be a plain name, found a map"),
            std::string::npos)
      << r.err;
}

TEST(PipelineLimits, AStudyLargerThanItsLimitIsRefusedUnlessRaised) {
  const fs::path dir = scratch_dir("limits-study");
  const std::string stages =
      "stages:\n"
      "  a: {tool: teststage, output: a.txt}\n"
      "study:\n";
  std::string axes = "  matrix:\n";
  // 9 axes of 10 values: 10^9 runs from 11 lines.
  for (int k = 0; k < 9; ++k) axes += "    a.x" + std::to_string(k) + ": [0,1,2,3,4,5,6,7,8,9]\n";
  auto r = validate_in(dir, stages + axes);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("pipe.yaml:4:3: the study expands to 1000000000 runs, more than "
                       "study.max_runs (1000): set max_runs if you mean it"),
            std::string::npos)
      << r.err;
  // 3 axes of 11 values: 1331 runs, allowed once the file asks for them.
  const std::string eleven = ": [0,1,2,3,4,5,6,7,8,9,10]\n";
  const std::string small = "  matrix:\n    a.x" + eleven + "    a.y" + eleven + "    a.z" + eleven;
  EXPECT_EQ(validate_in(dir, stages + small).exit_code, 2);
  r = validate_in(dir, stages + "  max_runs: 1331\n" + small);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("ok (1331 stages)"), std::string::npos) << r.out;
}

TEST(PipelineLimits, AChainOfFiftyThousandStagesIsChecked) {
  const fs::path dir = scratch_dir("limits-chain");
  std::string yaml = "workdir: out\nstages:\n  s0: {tool: teststage, output: f0.txt}\n";
  const int n = 50000;
  for (int i = 1; i < n; ++i)
    yaml += "  s" + std::to_string(i) + ": {tool: teststage, input: f" + std::to_string(i - 1) +
            ".txt, output: f" + std::to_string(i) + ".txt}\n";
  const auto r = validate_in(dir, yaml);
  EXPECT_EQ(r.exit_code, 0) << r.err.substr(0, 2000);
  EXPECT_NE(r.out.find("ok (50000 stages)"), std::string::npos) << r.out;
}
