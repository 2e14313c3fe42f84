// Cluster resources: every stage of `vesica export --snakemake` asks for threads, memory and
// time that cover what the stage was measured to need (docs/benchmarks.md and the peak
// memories measured with /usr/bin/time for docs/pipeline-file.md), from the mesh it works
// on; and Snakemake reads them as such.
#include <gtest/gtest.h>

#include <regex>

#include "PipelineTestSupport.h"
#include "vesica/pipelines/PipelineFile.h"
#include "vesica/pipelines/Plan.h"
#include "vesica/pipelines/StageResources.h"

namespace fs = std::filesystem;
using namespace vesica::test;
using namespace vesica::pipelines;

namespace {

struct Planned {
  Plan plan;
  std::string problems;
  const PlannedStage& stage(const std::string& id) const {
    return plan.stages[static_cast<std::size_t>(plan.index_of(id))];
  }
  StageResources resources(const std::string& id) const {
    return stage_resources(plan, static_cast<std::size_t>(plan.index_of(id)));
  }
};

Planned plan_of(const fs::path& file) {
  Diagnostics d;
  const PipelineSpec spec = load_pipeline_file(file.string(), d);
  Planned p;
  p.plan = build_plan(spec, {"", bin_dir()}, d);
  p.problems = d.format(file.string());
  return p;
}

// A mesh report as vesica-mesh writes it (the keys the resources read).
void write_mesh_report(const fs::path& path, long triangles, long tetrahedra) {
  write_text(
      path,
      nlohmann::json{{"triangle_count", triangles}, {"tetrahedron_count", tetrahedra}}.dump());
}

// surface -> mesh -> simulate with these simulate parameters, the mesh's report present.
Planned cystometry_on(const fs::path& dir, long triangles, long tetrahedra,
                      const std::string& simulate_params) {
  write_mesh_report(dir / "out" / ".vesica" / "mesh.json", triangles, tetrahedra);
  write_text(dir / "p.yaml",
             "workdir: out\n"
             "stages:\n"
             "  surface: {output: s.vtp, params: {shape: sphere, volume_ml: 300}}\n"
             "  mesh: {input: s.vtp, output: s.msh, params: {fluid: true}}\n"
             "  simulate: {input: s.msh, output: sim, params: {" +
                 simulate_params + "}}\n");
  return plan_of(dir / "p.yaml");
}

}  // namespace

TEST(StageResources, ALevelOneCystometryGetsTheTimeAndMemoryItWasMeasuredToNeed) {
  const fs::path dir = scratch_dir("resources-level1");
  // Measured, 50 -> 350 ml and voiding: docs/benchmarks.md's 9.88 s on 2,312 triangles
  // and 112 s on 16,928 (loaded machine); peaks of 91 MB on 1,710 triangles, 103 MB on
  // 3,692 and 139 MB on 8,876 (/usr/bin/time).
  const struct {
    long triangles;
    double seconds, mb;
  } measured[] = {{1710, 0.0, 91.0},
                  {2312, 9.88, 0.0},
                  {3692, 15.0, 103.0},
                  {8876, 0.0, 139.0},
                  {16928, 112.0, 0.0}};
  for (const auto& m : measured) {
    const Planned p = cystometry_on(dir, m.triangles, 0, "mu_kpa: 3, straining_kpa: 4");
    ASSERT_TRUE(p.problems.empty()) << p.problems;
    const StageResources r = p.resources("simulate");
    EXPECT_EQ(r.threads, 2);  // RunOptions::threads: the element loop's two threads
    EXPECT_GE(r.runtime_min * 60.0, 2.0 * m.seconds) << m.triangles << " triangles";
    EXPECT_GE(r.mem_mb, 1.5 * m.mb) << m.triangles << " triangles";
    EXPECT_NE(r.basis.find("level-1"), std::string::npos) << r.basis;
    EXPECT_NE(r.basis.find("(mesh.json)"), std::string::npos) << r.basis;
  }
}

TEST(StageResources, ALevelTwoCystometryAsksForItsHoursAndGigabytes) {
  const fs::path dir = scratch_dir("resources-level2");
  // Level 2 on the real CT bladder (22,205 tetrahedra): filling 50 -> 100 ml took 511 s
  // and 3 s of voiding 111 s (loaded machine); 100,507 tetrahedra peaked at 2,505 MB.
  Planned p = cystometry_on(dir, 2474, 22205,
                            "level: 2, mu_kpa: 3, capacity_ml: 100, residual_ml: 45, "
                            "straining_kpa: 4, max_void_s: 3");
  ASSERT_TRUE(p.problems.empty()) << p.problems;
  EXPECT_GE(p.resources("simulate").runtime_min * 60.0, 511.0 + 111.0);
  p = cystometry_on(dir, 8876, 100507, "level: 2, capacity_ml: 52, no_void: true");
  EXPECT_GE(p.resources("simulate").mem_mb, 2505);

  // A whole level-2 cystometry takes hours where level 1 on the same mesh takes minutes.
  const long level2 = cystometry_on(dir, 2474, 22205, "level: 2").resources("simulate").runtime_min;
  const long level1 = cystometry_on(dir, 2474, 22205, "").resources("simulate").runtime_min;
  EXPECT_GE(level2, 60);
  EXPECT_LE(level1, 10);
}

TEST(StageResources, SegmentationAndMeshingCoverTheirBenchmarks) {
  const fs::path dir = scratch_dir("resources-images");
  // docs/benchmarks.md: a 512×512×300 phantom at 0.8 mm segmented in 4.69 s with a peak of
  // 454 MB; mesh --fluid of 5,120 triangles into 47,002 tetrahedra in 2.23 s.
  write_mesh_report(dir / "out" / ".vesica" / "mesh.json", 5120, 47002);
  write_text(dir / "p.yaml",
             "workdir: out\n"
             "stages:\n"
             "  phantom: {output: ct, params: {spacing_mm: 0.8, fov_mm: '409.6,409.6,240'}}\n"
             "  segment: {input: ct, output: b.nii.gz, params: {seed: auto}}\n"
             "  surface: {input: b.nii.gz, output: b.vtp}\n"
             "  mesh: {input: b.vtp, output: b.msh, params: {fluid: true}}\n");
  const Planned p = plan_of(dir / "p.yaml");
  ASSERT_TRUE(p.problems.empty()) << p.problems;
  EXPECT_GE(p.resources("segment").mem_mb, 454);
  EXPECT_GE(p.resources("segment").runtime_min * 60.0, 2.0 * 4.69);
  EXPECT_NE(p.resources("segment").basis.find("78,643,200 voxels"), std::string::npos)
      << p.resources("segment").basis;
  EXPECT_GE(p.resources("mesh").runtime_min * 60.0, 2.0 * 2.23);
}

// Before anything ran, the wall is estimated from the surface's edge length and volume:
// within 30 % of the meshes vesica made (the demo's 6 mm edge on its 300 ml phantom gave
// 1,710 triangles; a 300 ml sphere remeshed at 2.6 mm gave 8,876).
TEST(StageResources, BeforeAnyRunTheWallIsEstimatedFromTheSurfacesEdge) {
  const fs::path dir = scratch_dir("resources-estimate");
  write_text(dir / "p.yaml",
             "workdir: out\n"
             "stages:\n"
             "  phantom: {output: ct, params: {bladder_ml: 300}}\n"
             "  segment: {input: ct, output: b.nii.gz}\n"
             "  surface: {input: b.nii.gz, output: b.vtp, params: {edge_mm: 6}}\n"
             "  mesh: {input: b.vtp, output: b.msh}\n"
             "  sphere: {tool: surface, output: s.vtp, params: {shape: sphere, volume_ml: 300, "
             "edge_mm: 2.6}}\n"
             "  spheremesh: {tool: mesh, input: s.vtp, output: s.msh}\n");
  const Planned p = plan_of(dir / "p.yaml");
  ASSERT_TRUE(p.problems.empty()) << p.problems;
  const auto near = [](double estimate, double made) {
    return std::abs(estimate / made - 1.0) < 0.3;
  };
  const MeshSize demo = mesh_size_for(p.plan, static_cast<std::size_t>(p.plan.index_of("mesh")));
  const MeshSize sphere =
      mesh_size_for(p.plan, static_cast<std::size_t>(p.plan.index_of("spheremesh")));
  EXPECT_TRUE(near(demo.triangles, 1710)) << demo.basis;
  EXPECT_TRUE(near(sphere.triangles, 8876)) << sphere.basis;
  EXPECT_NE(demo.basis.find("edge 6 mm"), std::string::npos) << demo.basis;
}

TEST(StageResources, SnakemakeReadsEachRulesThreadsMemoryAndTime) {
  const fs::path dir = scratch_dir("resources-snakemake");
  if (run_command("snakemake --version", dir).exit_code != 0) {
    if (running_in_ci()) FAIL() << "snakemake is not installed";
    GTEST_SKIP() << "snakemake is not installed";
  }
  write_mesh_report(dir / "out" / ".vesica" / "mesh.json", 16928, 0);
  write_text(dir / "p.yaml",
             "workdir: out\n"
             "stages:\n"
             "  surface: {output: s.vtp, params: {shape: sphere, volume_ml: 300, edge_mm: 2}}\n"
             "  mesh: {input: s.vtp, output: s.msh}\n"
             "  simulate: {input: s.msh, output: sim}\n"
             "  other: {tool: teststage, input: s.vtp, output: other.txt}\n");
  const Planned p = plan_of(dir / "p.yaml");
  ASSERT_TRUE(p.problems.empty()) << p.problems;
  const auto exported = run_vesica("export --snakemake " + quoted((dir / "p.yaml").string()), dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  write_text(dir / "Snakefile", exported.out);
  // A dry run lists every job with the threads and resources Snakemake will ask for.
  const auto dry = run_command(
      "cd " + quoted(dir.string()) + " && snakemake -s Snakefile -n --cores 4 --forceall", dir);
  ASSERT_EQ(dry.exit_code, 0) << dry.err << "\n" << exported.out;
  const std::string listing = dry.out + dry.err;
  for (const std::string id : {"surface", "mesh", "simulate"}) {
    const StageResources r = p.resources(id);
    // The job's paragraph: "rule stage_ID:" up to the next blank line; Snakemake prints
    // "threads:" only above 1.
    const auto at = listing.find("rule stage_" + id + ":");
    ASSERT_NE(at, std::string::npos) << id << "\n" << listing;
    const std::string job = listing.substr(at, listing.find("\n\n", at) - at);
    std::smatch threads, resources;
    const bool has_threads = std::regex_search(job, threads, std::regex("threads: (\\d+)"));
    ASSERT_TRUE(
        std::regex_search(job, resources, std::regex("resources: .*mem_mb=(\\d+).*runtime=(\\d+)")))
        << job;
    EXPECT_EQ(has_threads ? std::stoi(threads[1]) : 1, r.threads) << job;
    EXPECT_EQ(std::stol(resources[1]), r.mem_mb) << job;
    EXPECT_EQ(std::stol(resources[2]), r.runtime_min) << job;
  }
  // The fine sphere's cystometry asks for more time than its surface; a tool vesica does
  // not ship asks for nothing (the workflow's --default-resources apply).
  EXPECT_GT(p.resources("simulate").runtime_min, p.resources("surface").runtime_min);
  EXPECT_FALSE(p.resources("other").known);
  const auto other = exported.out.find("rule stage_other:");
  ASSERT_NE(other, std::string::npos);
  EXPECT_EQ(exported.out.find("resources:", other), std::string::npos);
}
