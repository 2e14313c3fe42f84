// Studies: variants and matrix runs share every stage they have in common, write their
// own copies under variants/<name>/, and rerun only what a change touches.
#include <gtest/gtest.h>

#include "PipelineTestSupport.h"
#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/StudyReport.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

std::string study_yaml(const std::string& stiff_label) {
  return "workdir: out\n"
         "stages:\n"
         "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
         "  b: {tool: teststage, input: a.txt, output: b/out.txt, params: {label: B}}\n"
         "  c: {tool: teststage, input: b/out.txt, output: c.txt, params: {label: C}}\n"
         "study:\n"
         "  variants:\n"
         "    soft: {b.label: B1}\n"
         "    stiff: {b.label: " +
         stiff_label +
         "}\n"
         "    late: {c.label: C9}\n";
}

}  // namespace

TEST(Study, VariantsShareCommonUpstreamStages) {
  const fs::path dir = scratch_dir("study-share");
  write_text(dir / "study.yaml", study_yaml("B2"));
  // a is shared by all; b is shared by `late` only; soft and stiff copy b and c.
  EXPECT_EQ(run_json(dir / "study.yaml", dir),
            (Ids{"a", "b@soft", "c@soft", "b@stiff", "c@stiff", "b", "c@late"}));
  EXPECT_EQ(slurp(dir / "out/variants/soft/c.txt"), "A\nB1\nC\n");
  EXPECT_EQ(slurp(dir / "out/variants/stiff/c.txt"), "A\nB2\nC\n");
  EXPECT_EQ(slurp(dir / "out/variants/late/c.txt"), "A\nB\nC9\n");
  EXPECT_EQ(slurp(dir / "out/b/out.txt"), "A\nB\n");
  EXPECT_TRUE(fs::exists(dir / "out/variants/soft/b/b.manifest.json"));
  EXPECT_FALSE(fs::exists(dir / "out/c.txt"));  // the unvaried c is used by no run
  EXPECT_EQ(run_json(dir / "study.yaml", dir), Ids{});
}

TEST(Study, ChangingOneVariantRerunsOnlyItsAffectedStages) {
  const fs::path dir = scratch_dir("study-change");
  write_text(dir / "study.yaml", study_yaml("B2"));
  ASSERT_EQ(run_json(dir / "study.yaml", dir).size(), 7u);
  write_text(dir / "study.yaml", study_yaml("B3"));
  const auto st = status_of(dir / "study.yaml", dir);
  EXPECT_EQ(st.at("b@stiff").second, "parameter label changed (B2 -> B3)");
  EXPECT_EQ(st.at("c@stiff").second, "upstream b@stiff is stale");
  EXPECT_EQ(st.at("c@soft").first, "fresh");
  EXPECT_EQ(run_json(dir / "study.yaml", dir, "-j 2"), (Ids{"b@stiff", "c@stiff"}));
  EXPECT_EQ(slurp(dir / "out/variants/stiff/c.txt"), "A\nB3\nC\n");
}

TEST(Study, MatrixIsTheCartesianProduct) {
  const fs::path dir = scratch_dir("study-matrix");
  const std::string yaml =
      "stages:\n"
      "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
      "  b: {tool: teststage, input: a.txt, output: b.txt, params: {label: B}}\n"
      "  c: {tool: teststage, input: b.txt, output: c.txt, params: {label: C}}\n"
      "study:\n"
      "  matrix:\n"
      "    b.label: [x, y]\n"
      "    c.label: [p, q]\n";
  write_text(dir / "m.yaml", yaml);
  vesica::pipelines::Diagnostics d;
  const auto plan = vesica::pipelines::build_plan(
      vesica::pipelines::parse_pipeline_text(yaml, dir / "m.yaml", d), {{}, bin_dir()}, d);
  ASSERT_TRUE(d.empty()) << d.format("m.yaml");
  // 1 shared a + 4 runs x (b, c).
  ASSERT_EQ(plan.stages.size(), 9u);
  EXPECT_EQ(plan.stages[0].id, "a");
  EXPECT_EQ(plan.stages[1].id, "b@label-x_label-p");
  EXPECT_EQ(plan.stages[2].argv[0], "variants/label-x_label-p/b.txt");
  EXPECT_EQ(run_json(dir / "m.yaml", dir, "-j 2").size(), 9u);
  EXPECT_EQ(slurp(dir / "variants/label-y_label-q/c.txt"), "A\ny\nq\n");
  EXPECT_EQ(slurp(dir / "variants/label-x_label-q/c.txt"), "A\nx\nq\n");
}

TEST(Study, UnknownStageInStudyIsSuggested) {
  const fs::path dir = scratch_dir("study-unknown");
  write_text(dir / "s.yaml",
             "stages:\n"
             "  simulate: {tool: teststage, output: s.txt}\n"
             "study:\n"
             "  variants:\n"
             "    v: {simulte.label: x}\n");
  const auto r = run_vesica("validate " + quoted((dir / "s.yaml").string()), dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("s.yaml:5:24: study names unknown stage 'simulte' (did you mean "
                       "'simulate'?)"),
            std::string::npos)
      << r.err;
}

TEST(Study, ReportHookFindsEachVariantsSimulation) {
  const fs::path dir = scratch_dir("study-report");
  const std::string yaml =
      "stages:\n"
      "  sim: {tool: simulate, output: sim, params: {mu_kpa: 5}}\n"
      "study:\n"
      "  matrix: {sim.mu_kpa: [5, 8]}\n";
  vesica::pipelines::Diagnostics d;
  const auto plan = vesica::pipelines::build_plan(
      vesica::pipelines::parse_pipeline_text(yaml, dir / "r.yaml", d), {dir, bin_dir()}, d);
  ASSERT_TRUE(d.empty()) << d.format("r.yaml");
  write_text(dir / "variants/mu_kpa-8/sim/summary.json", "{\"compliance_ml_per_cmh2o\": 40.5}");
  const auto report = vesica::pipelines::StudyReport::collect(plan);
  ASSERT_EQ(report.rows().size(), 2u);
  EXPECT_TRUE(report.rows()[0].summary.is_null());
  EXPECT_EQ(report.to_csv(), "variant,compliance_ml_per_cmh2o\nmu_kpa-5,\nmu_kpa-8,40.5\n");
}
