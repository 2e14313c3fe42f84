// `vesica export --snakemake`: Snakemake runs the same commands and produces byte-identical
// outputs (same content hashes) and the manifests `vesica run` would have written; and it
// keeps an edited intermediate as `vesica run` does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "PipelineTestSupport.h"
#include "vesica/core/ContentHash.h"

namespace fs = std::filesystem;
using namespace vesica::test;

namespace {

bool snakemake_missing(const fs::path& dir) {
  return run_command("snakemake --version", dir).exit_code != 0;
}

#define VESICA_REQUIRE_SNAKEMAKE(dir)                            \
  if (snakemake_missing(dir)) {                                  \
    if (running_in_ci()) FAIL() << "snakemake is not installed"; \
    GTEST_SKIP() << "snakemake is not installed";                \
  }

// Exports `file` for `workdir` and runs it with Snakemake.
CommandResult snakemake(const fs::path& file, const fs::path& workdir, const fs::path& dir) {
  auto exported = run_vesica(
      "export --snakemake " + quoted(file.string()) + " --workdir " + quoted(workdir.string()),
      dir);
  if (exported.exit_code != 0) return exported;
  write_text(dir / "Snakefile", exported.out);
  auto sm = run_command(
      "cd " + quoted(dir.string()) + " && snakemake -s Snakefile -j 2 --cores 2 --quiet", dir);
  sm.err += "\n" + exported.out;
  return sm;
}

// Runs `file` in `native` with `vesica run` and in `snake` with Snakemake; the number of
// stages `vesica run` ran.
std::size_t run_both(const fs::path& file, const fs::path& native, const fs::path& snake,
                     const fs::path& dir) {
  const std::size_t ran = run_json(file, dir, "--workdir " + quoted(native.string())).size();
  const auto sm = snakemake(file, snake, dir);
  EXPECT_EQ(sm.exit_code, 0) << sm.err;
  return ran;
}

}  // namespace

TEST(SnakemakeExport, SnakemakeProducesTheNativeRunnersOutputs) {
  const fs::path dir = scratch_dir("snakemake");
  VESICA_REQUIRE_SNAKEMAKE(dir);
  write_text(dir / "ext" / "measured.txt", "M\n");
  const fs::path file = dir / "p.yaml";
  write_text(file,
             "inputs: {measured: ext/measured.txt}\n"
             "stages:\n"
             "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
             "  b: {tool: teststage, input: a.txt, output: sim, params: {label: B, dir: true}}\n"
             "  c:\n"
             "    tool: teststage\n"
             "    input: sim/data.txt\n"
             "    inputs: {aux: '${inputs.measured}'}\n"
             "    output: report/c.txt\n"
             "    params: {label: C}\n"
             "study:\n"
             "  variants: {one: {}, two: {b.label: B2}}\n");
  const fs::path native = dir / "native", snake = dir / "snake";
  ASSERT_EQ(run_both(file, native, snake, dir), 5u);
  for (const std::string out :
       {"a.txt", "sim", "report/c.txt", "variants/two/sim", "variants/two/report/c.txt"})
    EXPECT_EQ(vesica::content_hash(snake / out), vesica::content_hash(native / out)) << out;
  EXPECT_EQ(slurp(snake / "variants/two/report/c.txt"), "A\nB2\nM\nC\n");
  // The manifests Snakemake's rules left make `vesica run` see everything as fresh.
  EXPECT_EQ(run_json(file, dir, "--workdir " + quoted(snake.string())), Ids{});
}

// The same edits in two workdirs, one run by `vesica run`, one by Snakemake: a file and a
// folder output edited by hand, each kept byte for byte, everything after them rerun.
TEST(SnakemakeExport, SnakemakeKeepsAnEditedIntermediateAsTheNativeRunnerDoes) {
  const fs::path dir = scratch_dir("snakemake-edit");
  VESICA_REQUIRE_SNAKEMAKE(dir);
  const fs::path file = dir / "p.yaml";
  write_text(file,
             "stages:\n"
             "  a: {tool: teststage, output: a.txt, params: {label: A}}\n"
             "  b: {tool: teststage, input: a.txt, output: b.txt, params: {label: B}}\n"
             "  c: {tool: teststage, input: b.txt, output: c.txt, params: {label: C}}\n"
             "  f: {tool: teststage, input: a.txt, output: fold, params: {label: F, dir: true}}\n"
             "  g: {tool: teststage, input: fold/data.txt, output: g.txt, params: {label: G}}\n");
  const fs::path native = dir / "native", snake = dir / "snake";
  ASSERT_EQ(run_both(file, native, snake, dir), 5u);
  for (const fs::path& w : {native, snake}) {
    write_text(w / "b.txt", "b edited by hand\n");
    write_text(w / "fold/data.txt", "fold edited by hand\n");
  }

  EXPECT_EQ(run_json(file, dir, "--workdir " + quoted(native.string())), (Ids{"c", "g"}));
  const auto second = snakemake(file, snake, dir);
  ASSERT_EQ(second.exit_code, 0) << second.err;

  EXPECT_EQ(slurp(snake / "b.txt"), "b edited by hand\n");
  EXPECT_EQ(slurp(snake / "c.txt"), "b edited by hand\nC\n");
  EXPECT_EQ(slurp(snake / "g.txt"), "fold edited by hand\nG\n");
  for (const std::string out : {"a.txt", "b.txt", "c.txt", "fold", "g.txt"})
    EXPECT_EQ(vesica::content_hash(snake / out), vesica::content_hash(native / out)) << out;
  EXPECT_FALSE(fs::exists(snake / ".vesica/backup"));
  // Either engine, then the other, finds nothing to do.
  EXPECT_EQ(run_json(file, dir, "--workdir " + quoted(snake.string())), Ids{});
  const auto again = snakemake(file, native, dir);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(slurp(native / "c.txt"), "b edited by hand\nC\n");
}

// The shipped neobladder study on a cluster: Snakemake reads its export and plans every
// stage of the 12 variants, their 24 fillings at the ends of the wall's uncertainty and
// the MR pouch's chain with its own 2 (a dry run: the study itself is
// `bench/bench_study.sh`'s), and
// each variant's simulation asks for the resources of its own pouch: a 60 cm tube has
// 1.5 times the 40 cm tube's tissue (L x C), so more triangles and more time.
TEST(SnakemakeExport, TheNeobladderStudyPlansEveryVariantWithItsOwnResources) {
  const fs::path dir = scratch_dir("snakemake-neobladder");
  VESICA_REQUIRE_SNAKEMAKE(dir);
  const fs::path file = source_dir() / "pipelines" / "neobladder-whatif.yaml";
  const auto exported = run_vesica("export --snakemake " + quoted(file.string()) + " --workdir " +
                                       quoted((dir / "work").string()),
                                   dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  write_text(dir / "Snakefile", exported.out);
  const auto dry =
      run_command("cd " + quoted(dir.string()) + " && snakemake -s Snakefile -n --cores 2", dir);
  ASSERT_EQ(dry.exit_code, 0) << dry.err << dry.out;
  // 12 pouches x (surface, mesh, simulate) + 24 fillings at the ends + the MR pouch's 5
  // stages + its 2 at the ends, and Snakemake's own rule `all`.
  const std::string log = dry.out + dry.err;
  const std::size_t total = log.find("\ntotal ");
  ASSERT_NE(total, std::string::npos) << log;
  EXPECT_EQ(std::stoi(log.substr(total + 7)), 12 * 3 + 24 + 5 + 2 + 1) << log;
  // The comment line above each rule's resources names the size it was estimated from.
  const auto basis = [&](const std::string& variant) {
    const std::string rule = "if \"simulate@shape-" + variant + "\" not in EDITED";
    const std::size_t at = exported.out.find(rule);
    if (at == std::string::npos) return std::string("nan");
    const std::size_t from = exported.out.find(" on about ", at) + 10;
    const std::size_t to = exported.out.find(" triangles", from);
    std::string n = exported.out.substr(from, to - from);  // "2,489"
    n.erase(std::remove(n.begin(), n.end(), ','), n.end());
    return n;
  };
  const double tube40 = std::stod(basis("tubular_ileum_length_cm-40"));
  const double tube60 = std::stod(basis("tubular_ileum_length_cm-60"));
  std::printf("[ snakemake ] simulate resources from about %.0f and %.0f triangles\n", tube40,
              tube60);
  EXPECT_NEAR(tube60 / tube40, 1.5, 0.05);
  // vesica-surface makes 2,424 triangles of the 40 cm tube at 6 mm edges.
  EXPECT_NEAR(tube40, 2424, 0.1 * 2424);
}

// The shipped study, cut to the 40 cm tube and the sphere of the same tissue, filled to
// 300 ml without voiding, run by Snakemake with its local executor: every variant's
// simulation completes, and Hinman's principle holds (P = 2T/r: the detubularized sphere
// holds the same volume at a lower pressure than the tube, or more before the limit).
TEST(SnakemakeExport, SnakemakeRunsTheNeobladderStudyAndTheSphereFillsAtLowerPressure) {
  const fs::path dir = scratch_dir("snakemake-neobladder-run");
  VESICA_REQUIRE_SNAKEMAKE(dir);
  std::string study = slurp(source_dir() / "pipelines" / "neobladder-whatif.yaml");
  const auto replace = [&](const std::string& from, const std::string& to) {
    const std::size_t at = study.find(from);
    ASSERT_NE(at, std::string::npos) << "the shipped study no longer says: " << from;
    study.replace(at, from.size(), to);
  };
  // Only the parametric pouches, without the wall's uncertainty (NeobladderStudyTest.cpp
  // runs those): the MR pouch's chain and the uncertainty's ends are cut out.
  const auto cut = [&](const std::string& from, const std::string& to) {
    const std::size_t at = study.find(from);
    ASSERT_NE(at, std::string::npos) << "the shipped study no longer says: " << from;
    const std::size_t end = to.empty() ? study.size() : study.find(to, at);
    ASSERT_NE(end, std::string::npos) << "the shipped study no longer says: " << to;
    study.erase(at, end - at);
  };
  cut("  # The MR-derived pouch", "\nstudy:");
  cut("  uncertainty:", "");
  replace("surface.shape: [tubular, studer, hautmann, sphere]", "surface.shape: [tubular, sphere]");
  replace("surface.ileum_length_cm: [40, 50, 60]", "surface.ileum_length_cm: [40]");
  replace("capacity_ml: 800", "capacity_ml: 300");
  replace("drive: straining", "no_void: true");
  write_text(dir / "study.yaml", study);
  const auto sm = snakemake(dir / "study.yaml", dir / "work", dir);
  ASSERT_EQ(sm.exit_code, 0) << sm.err;

  std::map<std::string, nlohmann::json> summary;  // by shape
  for (const auto& e : fs::directory_iterator(dir / "work" / "variants")) {
    const std::string name = e.path().filename().string();
    const std::string shape = name.find("sphere") != std::string::npos ? "sphere" : "tubular";
    summary[shape] = nlohmann::json::parse(slurp(e.path() / "sim" / "summary.json"));
    EXPECT_TRUE(summary[shape]["completed"].get<bool>()) << name;
  }
  ASSERT_EQ(summary.size(), 2u);
  const double v_tube = summary["tubular"]["capacity_ml"].get<double>();
  const double v_sphere = summary["sphere"]["capacity_ml"].get<double>();
  const double p_tube = summary["tubular"]["pdet_at_capacity_cmh2o"].get<double>();
  const double p_sphere = summary["sphere"]["pdet_at_capacity_cmh2o"].get<double>();
  std::printf("[ snakemake ] tube %.1f ml at %.2f cmH2O, sphere %.1f ml at %.2f cmH2O\n", v_tube,
              p_tube, v_sphere, p_sphere);
  EXPECT_GE(v_sphere, v_tube - 1e-6);
  if (v_sphere - v_tube < 1e-6) EXPECT_LT(p_sphere, p_tube);
}
