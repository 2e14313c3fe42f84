// `vesica export --snakemake`: Snakemake runs the same commands and produces byte-identical
// outputs (same content hashes) and the manifests `vesica run` would have written.
#include <gtest/gtest.h>

#include "PipelineTestSupport.h"
#include "vesica/core/ContentHash.h"

namespace fs = std::filesystem;
using namespace vesica::test;

TEST(SnakemakeExport, SnakemakeProducesTheNativeRunnersOutputs) {
  const fs::path dir = scratch_dir("snakemake");
  if (run_command("snakemake --version", dir).exit_code != 0) {
    if (running_in_ci()) FAIL() << "snakemake is not installed";
    GTEST_SKIP() << "snakemake is not installed";
  }
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
  ASSERT_EQ(run_json(file, dir, "--workdir " + quoted(native.string())).size(), 5u);

  const auto exported = run_vesica(
      "export --snakemake " + quoted(file.string()) + " --workdir " + quoted(snake.string()), dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  write_text(dir / "Snakefile", exported.out);
  const auto sm = run_command(
      "cd " + quoted(dir.string()) + " && snakemake -s Snakefile -j 2 --cores 2 --quiet", dir);
  ASSERT_EQ(sm.exit_code, 0) << sm.err << "\n" << exported.out;

  for (const std::string out :
       {"a.txt", "sim", "report/c.txt", "variants/two/sim", "variants/two/report/c.txt"})
    EXPECT_EQ(vesica::content_hash(snake / out), vesica::content_hash(native / out)) << out;
  EXPECT_EQ(slurp(snake / "variants/two/report/c.txt"), "A\nB2\nM\nC\n");
  // The manifests Snakemake's rules left make `vesica run` see everything as fresh.
  EXPECT_EQ(run_json(file, dir, "--workdir " + quoted(snake.string())), Ids{});
}
