// Studies: variants and matrix runs share every stage they have in common, write their
// own copies under variants/<name>/, and rerun only what a change touches.
#include <gtest/gtest.h>

#include "PipelineTestSupport.h"
#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/StudyAnswer.h"
#include "vesica/pipelines/StudyPage.h"
#include "vesica/pipelines/StudyRanking.h"
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

// The plan of a pipeline file's text in `dir` (its diagnostics a test failure).
vesica::pipelines::Plan plan_of(const std::string& yaml, const fs::path& dir) {
  vesica::pipelines::Diagnostics d;
  auto plan = vesica::pipelines::build_plan(
      vesica::pipelines::parse_pipeline_text(yaml, dir / "r.yaml", d), {dir, bin_dir()}, d);
  EXPECT_TRUE(d.empty()) << d.format("r.yaml");
  return plan;
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
  EXPECT_TRUE(fs::exists(dir / "out/.vesica/b@soft.manifest.json"));
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

// study.csv from hand-written simulation outputs, every number worked out by hand:
// mu_kpa-5 never ran, mu_kpa-8 filled 100 -> 500 ml and voided, mu_kpa-12 failed at 200 ml.
TEST(Study, TableHasOneRowPerVariantWithFailures) {
  const fs::path dir = scratch_dir("study-report");
  const std::string yaml =
      "stages:\n"
      "  sim: {tool: simulate, output: sim, params: {mu_kpa: 5, no_series: true}}\n"
      "study:\n"
      "  matrix: {sim.mu_kpa: [5, 8, 12]}\n";
  const auto plan = plan_of(yaml, dir);
  const std::string header = "time_s,volume_ml,pdet_cmh2o,flow_ml_s\n";
  write_text(dir / "variants/mu_kpa-8/sim/summary.json",
             R"({"completed": true, "qmax_ml_s": 20, "pvr_ml": 439, "max_wall_stress_kpa": 31})");
  write_text(dir / "variants/mu_kpa-8/sim/history.csv",
             header +
                 "0,100,0,0\n120,200,5,0\n240,300,10,0\n360,400,30,0\n420,450,50,0\n"
                 "480,500,60,0\n481,480,65,20\n483,439,5,0\n");
  write_text(dir / "variants/mu_kpa-12/sim/summary.json",
             R"({"completed": false, "failure": "step failed at t = 120 s, V = 200 ml: stalled"})");
  write_text(dir / "variants/mu_kpa-12/sim/history.csv",
             header + "0,100,0,0\n60,150,2,0\n120,200,5,0\n");
  const auto report = vesica::pipelines::StudyReport::collect(plan);
  ASSERT_EQ(report.rows().size(), 3u);
  EXPECT_EQ(report.to_csv(),
            "variant,status,answer,sim.mu_kpa,built_volume_ml,pdet_at_300ml_cmh2o,"
            "pdet_at_500ml_cmh2o,max_pdet_cmh2o,compliance_ml_per_cmh2o,capacity_at_40cmh2o_ml,"
            "qmax_ml_s,voided_ml,pvr_ml,"
            "stress_p95_at_capacity_kpa,stress_max_at_capacity_kpa,stress_max_where,failure\n"
            "mu_kpa-5,not run,,5,,,,,,,,,,,,,no summary.json yet\n"
            // 40 cmH2O between 400 ml @ 30 and 450 ml @ 50; compliance 400 ml / 60 cmH2O; no
            // series, so no stress at capacity
            "mu_kpa-8,ok,,8,,10,60,65,6.66667,425,20,,439,,,,\n"
            // never reached 300 ml; capacity above the 200 ml reached; 100 ml / 5 cmH2O
            "mu_kpa-12,failed,,12,,,,5,20,>200,,,,,,,"
            "\"step failed at t = 120 s, V = 200 ml: stalled\"\n");
}

// The answer to a study's question from its limits, worked by hand.
TEST(Study, AnswerIsPassOnlyWhenEveryLimitHolds) {
  using vesica::pipelines::StudyLimit;
  using vesica::pipelines::StudyValue;
  const std::vector<StudyLimit> limits = {{"pdet_at_500ml_cmh2o", std::nullopt, 40.0, {}},
                                          {"capacity_at_40cmh2o_ml", 450.0, std::nullopt, {}}};
  auto answer = [&](std::optional<double> pdet, StudyValue capacity) {
    return vesica::pipelines::answer(
        limits, {{"pdet_at_500ml_cmh2o", {pdet}}, {"capacity_at_40cmh2o_ml", capacity}});
  };
  EXPECT_EQ(answer(12.0, {520.0}), "pass");
  EXPECT_EQ(answer(40.0, {450.0}), "pass");            // the limits are inclusive
  EXPECT_EQ(answer(41.0, {520.0}), "fail");            // Pdet over 40 at 500 ml
  EXPECT_EQ(answer(12.0, {430.0}), "fail");            // 40 cmH2O reached at 430 < 450 ml
  EXPECT_EQ(answer(12.0, {500.0, true}), "pass");      // "> 500": never reached 40
  EXPECT_EQ(answer(std::nullopt, {500.0, true}), "");  // 500 ml never reached: no answer
  EXPECT_EQ(answer(41.0, {std::nullopt}), "fail");     // one failing limit decides
  EXPECT_EQ(vesica::pipelines::limit_text(limits[0]), "Pdet at 500 ml <= 40 cmH2O");
}

TEST(Study, LimitsNameAReadOutAndNumbers) {
  vesica::pipelines::Diagnostics d;
  const auto spec = vesica::pipelines::parse_pipeline_text(
      "stages:\n"
      "  sim: {tool: simulate, output: sim}\n"
      "study:\n"
      "  question: Under 40 at 500 ml?\n"
      "  limits:\n"
      "    pdet_at_500ml_cmh2o: {max: 40}\n"
      "    pdet_at_500_cmh2o: {max: 40}\n"
      "    qmax_ml_s: {min: ten}\n"
      "  matrix: {sim.mu_kpa: [1, 2]}\n",
      "s.yaml", d);
  EXPECT_EQ(spec.study.question, "Under 40 at 500 ml?");
  ASSERT_EQ(spec.study.limits.size(), 1u);
  EXPECT_EQ(spec.study.limits[0].max, 40.0);
  const std::string text = d.format("s.yaml");
  EXPECT_NE(text.find("s.yaml:7:5: unknown study read-out 'pdet_at_500_cmh2o' (did you mean "
                      "'pdet_at_500ml_cmh2o'?)"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("s.yaml:8:22: study.limits.qmax_ml_s.min must be a number"),
            std::string::npos)
      << text;
}

TEST(Study, TableNamesTheFailureOfTheRunThatJustHappened) {
  const fs::path dir = scratch_dir("study-report-run");
  const std::string yaml =
      "stages:\n"
      "  mesh: {tool: mesh, input: in.vtp, output: m.msh, params: {thickness_mm: 3}}\n"
      "  sim: {tool: simulate, input: m.msh, output: sim, params: {mu_kpa: 5}}\n"
      "study:\n"
      "  variants: {thin: {mesh.thickness_mm: 2}, soft: {sim.mu_kpa: 1}}\n";
  write_text(dir / "in.vtp", "");
  const auto plan = plan_of(yaml, dir);
  vesica::pipelines::RunResult run;
  for (const auto& s : plan.stages) {
    vesica::pipelines::StageOutcome o;
    o.id = s.id;
    o.action = s.id == "mesh@thin" ? "failed" : s.id == "sim@thin" ? "blocked" : "ran";
    if (o.action == "failed") o.exit_code = 1, o.last_line = "vesica-mesh: error: in.vtp: empty";
    run.stages.push_back(o);
  }
  const auto report = vesica::pipelines::StudyReport::collect(plan, &run);
  ASSERT_EQ(report.rows().size(), 2u);
  EXPECT_EQ(report.rows()[0].variant, "thin");
  EXPECT_EQ(report.rows()[0].status, "failed");
  EXPECT_EQ(report.rows()[0].failure,
            "mesh@thin failed (exit 1): vesica-mesh: error: in.vtp: empty");
  // The varied parameters of both stages are columns; the shared ones are not.
  EXPECT_EQ(report.varied_parameters(), (Ids{"mesh.thickness_mm", "sim.mu_kpa"}));
}

TEST(Study, KeepGoingRunsTheVariantsAFailureDoesNotTouch) {
  const fs::path dir = scratch_dir("study-keep-going");
  write_text(dir / "study.yaml",
             "workdir: out\n"
             "stages:\n"
             "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
             "  b: {tool: teststage, input: a.txt, output: b.txt, params: {label: B}}\n"
             "  c: {tool: teststage, input: b.txt, output: c.txt, params: {label: C}}\n"
             "study:\n"
             "  variants: {bad: {b.fail: true}, good: {c.label: C2}}\n");
  int code = 0;
  // Without --keep-going the run stops at the first failure (b@bad runs first).
  EXPECT_EQ(run_json(dir / "study.yaml", dir, "", &code), Ids{"a"});
  EXPECT_EQ(code, 1);
  EXPECT_EQ(run_json(dir / "study.yaml", dir, "--keep-going", &code), (Ids{"b", "c@good"}));
  EXPECT_EQ(code, 1);
  EXPECT_EQ(slurp(dir / "out/variants/good/c.txt"), "A\nB\nC2\n");
}

// vesica-simulate writes its results and manifest for a run that stalls, then exits 1.
TEST(Study, AStageThatFailsAfterWritingRunsAgainNextTime) {
  const fs::path dir = scratch_dir("study-fail-after-writing");
  write_text(
      dir / "s.yaml",
      "stages:\n"
      "  a: {tool: teststage, output: a.txt, params: {label: A, fail_after_writing: true}}\n");
  int code = 0;
  EXPECT_EQ(run_json(dir / "s.yaml", dir, "", &code), Ids{});
  EXPECT_EQ(code, 1);
  EXPECT_EQ(slurp(dir / "a.txt"), "A\n");  // its results stay
  EXPECT_EQ(status_of(dir / "s.yaml", dir).at("a").first, "failed");
  EXPECT_EQ(run_json(dir / "s.yaml", dir, "", &code), Ids{});  // it runs again (and fails)
  EXPECT_EQ(code, 1);
  EXPECT_FALSE(fs::exists(dir / ".vesica/backup"));  // its own results, nobody's edit
}

// The page's answer ranks the variants by their capacity under 40 cmH2O, worked out by
// hand from hand-written histories: "tube" reaches 40 cmH2O at 350 ml (between 300 ml @ 20
// and 400 ml @ 60), "pouch" and "sphere" stay below it to 800 ml (lower bounds), the
// sphere with the lower Pdet at 500 ml (6 against 8 cmH2O).
TEST(Study, AnswerRanksVariantsByCapacityUnderTheLimit) {
  const fs::path dir = scratch_dir("study-ranking");
  const std::string yaml =
      "stages:\n"
      "  sim: {tool: simulate, output: sim, params: {mu_kpa: 5, no_series: true}}\n"
      "study:\n"
      "  variants: {tube: {sim.mu_kpa: 1}, pouch: {sim.mu_kpa: 2}, sphere: {sim.mu_kpa: 3}}\n";
  const auto plan = plan_of(yaml, dir);
  const std::string header = "time_s,volume_ml,pdet_cmh2o,flow_ml_s\n";
  const auto write = [&](const std::string& run, const std::string& rows) {
    write_text(dir / "variants" / run / "sim/summary.json", R"({"completed": true})");
    write_text(dir / "variants" / run / "sim/history.csv", header + rows);
  };
  write("tube", "0,50,10,0\n300,300,20,0\n400,400,60,0\n");
  write("pouch", "0,50,1,0\n540,500,8,0\n900,800,12,0\n");
  write("sphere", "0,50,1,0\n540,500,6,0\n900,800,10,0\n");
  const auto report = vesica::pipelines::StudyReport::collect(plan);
  const auto order = vesica::pipelines::rank_by_capacity(report);
  ASSERT_EQ(order.size(), 3u);
  EXPECT_EQ(report.rows()[order[0]].variant, "sphere");
  EXPECT_EQ(report.rows()[order[1]].variant, "pouch");
  EXPECT_EQ(report.rows()[order[2]].variant, "tube");
  EXPECT_EQ(vesica::pipelines::capacity_answer(report),
            "Largest capacity under 40 cmH2O: sphere (at least 800 ml, never reaching the "
            "limit), as did pouch (ranked by their lower Pdet at 500 ml); smallest: tube "
            "(350 ml).");

  // Without the tube, no filling came within a quarter of the limit: the answer says so.
  write("tube", "0,50,1,0\n540,500,7,0\n900,800,11,0\n");
  EXPECT_EQ(vesica::pipelines::capacity_answer(vesica::pipelines::StudyReport::collect(plan)),
            "No variant approached the 40 cmH2O limit: the highest filling Pdet of any was "
            "12.0 cmH2O, and every pouch held at least 800 ml below it; the ranking follows "
            "Pdet at 500 ml.");
}

// The uncertainty's ends bound every run: each run is followed by one run per end, which
// copies only what the end changes and reads the rest from its run (b@label-x), and a
// stage every run shares is run once per end, not once per run (d@lo).
TEST(Study, UncertaintyEndsBoundEveryRunAndCopyOnlyWhatTheyChange) {
  const fs::path dir = scratch_dir("study-uncertainty");
  const std::string yaml =
      "stages:\n"
      "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
      "  b: {tool: teststage, input: a.txt, output: b.txt, params: {label: B}}\n"
      "  c: {tool: teststage, input: b.txt, output: c.txt, params: {label: C}}\n"
      "  d: {tool: teststage, input: a.txt, output: d.txt, params: {label: D}}\n"
      "study:\n"
      "  matrix: {b.label: [x, y]}\n"
      "  uncertainty:\n"
      "    lo: {c.label: C-, d.label: D-}\n"
      "    hi: {c.label: C+, d.label: D+}\n";
  write_text(dir / "u.yaml", yaml);
  const auto plan = plan_of(yaml, dir);
  std::vector<std::string> ids;
  for (const auto& s : plan.stages) ids.push_back(s.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"a", "b@label-x", "c@label-x", "d", "c@label-x_lo",
                                           "d@lo", "c@label-x_hi", "d@hi", "b@label-y", "c@label-y",
                                           "c@label-y_lo", "c@label-y_hi"}));
  EXPECT_EQ(run_json(dir / "u.yaml", dir, "-j 2").size(), 12u);
  EXPECT_EQ(slurp(dir / "variants/label-x_lo/c.txt"), "A\nx\nC-\n");
  EXPECT_EQ(slurp(dir / "variants/label-y_hi/c.txt"), "A\ny\nC+\n");
  EXPECT_EQ(slurp(dir / "variants/lo/d.txt"), "A\nD-\n");
  EXPECT_EQ(slurp(dir / "d.txt"), "A\nD\n");
  EXPECT_EQ(run_json(dir / "u.yaml", dir), Ids{});
}

// The ranking read again at each end, from hand-written histories (capacities where Pdet
// first reaches 40 cmH2O, worked out by hand): as given, residual 20 holds 400 ml and
// residual 40 300 ml; with the soft wall >500 and 450 ml; with the stiff wall 300 and
// 350 ml, where the order turns over.
TEST(Study, RankingIsReportedRobustOnlyWhenItHoldsAtEveryEnd) {
  const fs::path dir = scratch_dir("study-robust");
  const std::string yaml =
      "stages:\n"
      "  sim: {tool: simulate, output: sim, params: {mu_kpa: 5, no_series: true}}\n"
      "study:\n"
      "  matrix: {sim.residual_ml: [20, 40]}\n"
      "  uncertainty: {soft: {sim.mu_kpa: 2}, stiff: {sim.mu_kpa: 9}}\n";
  const auto plan = plan_of(yaml, dir);
  const std::string header = "time_s,volume_ml,pdet_cmh2o,flow_ml_s\n";
  const auto write = [&](const std::string& run, const std::string& rows) {
    write_text(dir / "variants" / run / "sim/summary.json", R"({"completed": true})");
    write_text(dir / "variants" / run / "sim/history.csv", header + rows);
  };
  write("residual_ml-20", "0,100,0,0\n120,200,10,0\n240,300,20,0\n360,400,40,0\n");
  write("residual_ml-40", "0,100,0,0\n120,200,20,0\n240,300,40,0\n");
  write("residual_ml-20_soft", "0,100,0,0\n480,500,20,0\n");
  write("residual_ml-40_soft", "0,100,0,0\n240,300,20,0\n360,400,30,0\n420,450,40,0\n");
  write("residual_ml-20_stiff", "0,100,0,0\n120,200,20,0\n240,300,40,0\n");
  write("residual_ml-40_stiff", "0,100,0,0\n120,200,15,0\n240,300,30,0\n300,350,40,0\n");
  auto report = vesica::pipelines::StudyReport::collect(plan);
  ASSERT_EQ(report.rows().size(), 2u);  // the ends are bands of their runs, not rows
  ASSERT_EQ(report.bounds_of(report.rows()[0]).size(), 2u);
  EXPECT_EQ(report.uncertainty_ends(), (std::vector<std::string>{"soft", "stiff"}));
  EXPECT_EQ(vesica::pipelines::robustness_answer(report),
            "Not robust to the wall's uncertainty: residual_ml-20 ranks first as given, but "
            "residual_ml-40 at the stiff end.");
  const std::string csv = report.to_csv();
  EXPECT_EQ(csv.substr(0, csv.find('\n')).rfind("variant,status,answer,uncertainty,", 0), 0u)
      << csv;
  EXPECT_NE(csv.find("\nresidual_ml-20_stiff,ok,,stiff,"), std::string::npos) << csv;
  // The page: the capacity's interval across the ends under the value, and a band per run
  // on each filling plot.
  const std::string page = vesica::pipelines::study_html(report, "robust");
  EXPECT_NE(page.find("400<br><small class=\"interval\">300&ndash;&gt;500</small>"),
            std::string::npos);
  std::size_t areas = 0;
  for (std::size_t at = page.find("class=\"area\""); at != std::string::npos;
       at = page.find("class=\"area\"", at + 1))
    ++areas;
  EXPECT_EQ(areas, 4u);  // 2 runs x 2 filling plots
  EXPECT_NE(page.find("id=\"robustness-sentence\""), std::string::npos);
  EXPECT_NE(page.find("soft: mu_kpa 2; stiff: mu_kpa 9"), std::string::npos);

  // With a stiff residual 20 that still holds more (360 ml), the ranking holds at both ends.
  write("residual_ml-20_stiff", "0,100,0,0\n120,200,20,0\n240,300,30,0\n300,360,40,0\n");
  report = vesica::pipelines::StudyReport::collect(plan);
  EXPECT_EQ(vesica::pipelines::robustness_answer(report),
            "Robust to the wall's uncertainty: residual_ml-20 ranks first at the soft and stiff "
            "ends of its ranges too, and the whole order is the same.");
}
