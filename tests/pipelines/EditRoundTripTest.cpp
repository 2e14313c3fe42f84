// Intermediates edited the way 3D Slicer, MeshLab, ParaView and Gmsh save them, in a real
// pipeline (phantom -> segment -> surface -> mesh [-> simulate]): after `vesica run` the
// edited file is byte for byte what the user saved, the stages after it were rerun on it
// and their numbers follow from the edit (worked out here from the edit alone), the
// surface's regions survive, and a second run does nothing. A PLY edit gives the same
// files under the Snakemake export, and `vesica reset` brings the generated file back,
// the edit kept in the backup.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "PipelineTestSupport.h"
#include "ToolEdits.h"
#include "vesica/core/ContentHash.h"
#include "vesica/io/LabelMap.h"
#include "vesica/io/MshFile.h"
#include "vesica/io/SlicerSegmentation.h"
#include "vesica/io/SurfaceFile.h"
#include "vesica/io/VtuFile.h"

namespace fs = std::filesystem;
using namespace vesica::test;
using vesica::content_hash;
namespace io = vesica::io;

namespace {

// A 150 ml ellipsoidal bladder in a 3 mm CT, segmented, surfaced with an automatic
// outlet, meshed with its urine; `label` and `surface` name the intermediates.
std::string pipeline_yaml(const std::string& label, const std::string& surface,
                          bool simulate = false) {
  std::string yaml =
      "workdir: out\n"
      "stages:\n"
      "  phantom: {output: phantom/dicom, params: {bladder_ml: 150, spacing_mm: 3, shape: "
      "ellipsoid}}\n"
      "  segment: {input: phantom/dicom, output: " +
      label +
      ", params: {seed: auto}}\n"
      "  surface: {input: " +
      label + ", output: " + surface +
      ", params: {edge_mm: 8, outlet: auto}}\n"
      "  mesh: {input: " +
      surface + ", output: bladder.msh, params: {thickness_mm: 3, fluid: true}}\n";
  if (simulate)
    yaml +=
        "  simulate: {input: bladder.msh, output: sim, params: {capacity_ml: 80, no_void: true, "
        "no_series: true}}\n";
  return yaml;
}

struct Workdir {
  fs::path dir, file, out;
  Workdir(const std::string& name, const std::string& yaml) : dir(scratch_dir(name)) {
    file = dir / "p.yaml";
    out = dir / "out";
    write_text(file, yaml);
  }
  nlohmann::json report(const std::string& stage) const {
    return nlohmann::json::parse(slurp(out / ".vesica" / (stage + ".json")));
  }
  nlohmann::json run(const std::string& extra = "") const {
    const CommandResult r = run_vesica("run " + quoted(file.string()) + " --json " + extra, dir);
    auto j = nlohmann::json::parse(r.out, nullptr, false);
    if (j.is_discarded()) j = {{"ran", {"<no JSON: " + r.err + ">"}}};
    return j;
  }
  Ids ran(const std::string& extra = "") const { return run(extra)["ran"].get<Ids>(); }
};

// The lines a stage printed in a `run --json` result.
std::string log_of(const nlohmann::json& run, const std::string& stage) {
  std::string text;
  for (const auto& s : run["stages"])
    if (s["id"] == stage)
      for (const auto& line : s["log"]) text += line.get<std::string>() + "\n";
  return text;
}

double relative(double a, double b) {
  return std::abs(a - b) / std::abs(b);
}

// Area (mm2) of the triangles of a region in the mesh stage's .vtu.
double region_area_mm2(const fs::path& vtu, int region) {
  const io::VolumeMesh m = io::read_mesh_vtu(vtu);
  double area = 0;
  for (Eigen::Index t = 0; t < m.triangles.rows(); ++t) {
    if (m.tri_region(t) != region) continue;
    const Eigen::Vector3d a = m.nodes.row(m.triangles(t, 0)), b = m.nodes.row(m.triangles(t, 1)),
                          c = m.nodes.row(m.triangles(t, 2));
    area += 0.5 * (b - a).cross(c - a).norm();
  }
  return area;
}

// The label map edits: the surface and the mesh enclose exactly the painted label's voxels
// (the surface stage rescales to the label's voxel volume).
void expect_volume_follows_the_label(const Workdir& w, const fs::path& label, long changed) {
  const std::string saved = content_hash(label);
  const nlohmann::json before = w.report("surface");
  EXPECT_EQ(status_of(w.file, w.dir).at("segment").first, "edited");
  EXPECT_EQ(w.ran(), (Ids{"surface", "mesh"}));
  EXPECT_EQ(content_hash(label), saved);
  const double voxel_mm3 =
      before["label_volume_ml"].get<double>() * 1000.0 / before["label_voxel_count"].get<double>();
  const double expected_ml =
      (before["label_voxel_count"].get<long>() + changed) * voxel_mm3 / 1000.0;
  EXPECT_EQ(w.report("surface")["label_voxel_count"].get<long>(),
            before["label_voxel_count"].get<long>() + changed);
  // The surface is stored as float32 PLY: 1e-6 covers its rounding.
  EXPECT_LT(relative(w.report("mesh")["enclosed_volume_ml"], expected_ml), 1e-6)
      << w.report("mesh")["enclosed_volume_ml"] << " vs " << expected_ml;
  EXPECT_GT(w.report("mesh")["region_triangle_counts"].value("outlet", 0), 0);
  EXPECT_EQ(w.ran(), Ids{});
}

}  // namespace

TEST(EditRoundTrip, ASurfaceEnlargedInParaViewIsKeptAndTheMeshEnclosesItsVolume) {
  const Workdir w("edit-vtp", pipeline_yaml("bladder.nii.gz", "bladder.vtp"));
  ASSERT_EQ(w.ran().size(), 4u);
  const nlohmann::json before = w.report("mesh");
  enlarge_in_paraview(w.out / "bladder.vtp");
  const std::string saved = content_hash(w.out / "bladder.vtp");
  const auto st = status_of(w.file, w.dir);
  EXPECT_EQ(st.at("surface"), std::make_pair(std::string("edited"), std::string("bladder.vtp")));
  EXPECT_EQ(st.at("mesh").second, "input bladder.vtp changed (upstream surface)");

  EXPECT_EQ(w.ran(), Ids{"mesh"});
  EXPECT_EQ(content_hash(w.out / "bladder.vtp"), saved);
  const nlohmann::json after = w.report("mesh");
  // A similarity of ratio 1.1 scales every volume by 1.1^3.
  EXPECT_NEAR(
      after["enclosed_volume_ml"].get<double>() / before["enclosed_volume_ml"].get<double>(), 1.331,
      1e-9);
  EXPECT_EQ(after["region_triangle_counts"], before["region_triangle_counts"]);  // the .vtp's own
  EXPECT_EQ(w.ran(), Ids{});
}

TEST(EditRoundTrip, APlySubdividedInMeshLabIsRetaggedMeshedAndKeptByBothEngines) {
  const Workdir w("edit-ply", pipeline_yaml("bladder.nii.gz", "bladder.ply"));
  const fs::path native = w.dir / "native", snake = w.dir / "snake";
  const std::string in_native = "--workdir " + quoted(native.string());
  ASSERT_EQ(w.ran(in_native).size(), 4u);
  const auto exported = run_vesica(
      "export --snakemake " + quoted(w.file.string()) + " --workdir " + quoted(snake.string()),
      w.dir);
  ASSERT_EQ(exported.exit_code, 0) << exported.err;
  write_text(w.dir / "Snakefile", exported.out);
  const std::string snakemake =
      "cd " + quoted(w.dir.string()) + " && snakemake -s Snakefile -j 1 --cores 1 --quiet";
  const bool with_snakemake = run_command("snakemake --version", w.dir).exit_code == 0;
  if (!with_snakemake && running_in_ci()) FAIL() << "snakemake is not installed";
  if (with_snakemake) {
    ASSERT_EQ(run_command(snakemake, w.dir).exit_code, 0);
  }

  const nlohmann::json before = nlohmann::json::parse(slurp(native / ".vesica/mesh.json"));
  const double outlet_before = region_area_mm2(native / "bladder.vtu", 2);
  const std::string generated = content_hash(native / "bladder.ply");
  subdivide_in_meshlab(native / "bladder.ply");
  if (with_snakemake) subdivide_in_meshlab(snake / "bladder.ply");
  const std::string saved = content_hash(native / "bladder.ply");

  const nlohmann::json run = w.run(in_native);
  EXPECT_EQ(run["ran"], Ids{"mesh"});
  EXPECT_EQ(run["kept"], Ids{"bladder.ply (surface)"});
  const long triangles = before["triangle_count"];
  // The mesh stage says it re-tagged the triangles by their nearest recorded centroid.
  EXPECT_NE(log_of(run, "mesh")
                .find(std::to_string(triangles) + " region tags for " +
                      std::to_string(4 * triangles) + " triangles"),
            std::string::npos)
      << log_of(run, "mesh");
  EXPECT_EQ(content_hash(native / "bladder.ply"), saved);
  const nlohmann::json after = nlohmann::json::parse(slurp(native / ".vesica/mesh.json"));
  EXPECT_EQ(after["triangle_count"].get<long>(), 4 * triangles);  // each triangle split in 4
  // Midpoint subdivision keeps the polyhedron: the same volume, up to float32 midpoints.
  EXPECT_LT(relative(after["enclosed_volume_ml"], before["enclosed_volume_ml"]), 1e-6);
  // The outlet is still there, about as large: its triangles' children took its tag.
  EXPECT_LT(relative(region_area_mm2(native / "bladder.vtu", 2), outlet_before), 0.15);
  EXPECT_EQ(w.ran(in_native), Ids{});

  if (with_snakemake) {
    ASSERT_EQ(run_command(snakemake, w.dir).exit_code, 0);
    for (const std::string f : {"bladder.ply", "bladder.msh", "bladder.vtu"})
      EXPECT_EQ(content_hash(snake / f), content_hash(native / f)) << f;
  }

  const CommandResult reset =
      run_vesica("reset " + quoted(w.file.string()) + " surface " + in_native, w.dir);
  EXPECT_EQ(reset.exit_code, 0) << reset.err;
  EXPECT_EQ(content_hash(native / "bladder.ply"), generated);
  std::vector<fs::path> backups;
  for (const auto& e : fs::directory_iterator(native / ".vesica/backup/surface"))
    backups.push_back(e.path());
  ASSERT_EQ(backups.size(), 1u);
  EXPECT_EQ(content_hash(backups[0] / "bladder.ply"), saved);
  EXPECT_EQ(nlohmann::json::parse(slurp(native / ".vesica/mesh.json"))["triangle_count"],
            triangles);
}

TEST(EditRoundTrip, ALabelMapPaintedInSlicerIsKeptAndTheSurfaceEnclosesItsVoxels) {
  const Workdir w("edit-nifti", pipeline_yaml("bladder.nii.gz", "bladder.ply"));
  ASSERT_EQ(w.ran().size(), 4u);
  const long painted = paint_in_slicer(w.out / "bladder.nii.gz", 2);
  ASSERT_GT(painted, 100);
  expect_volume_follows_the_label(w, w.out / "bladder.nii.gz", painted);
}

TEST(EditRoundTrip, ASlicerSegmentationEditedInTheSegmentEditorIsKept) {
  const Workdir w("edit-seg-nrrd", pipeline_yaml("bladder.seg.nrrd", "bladder.ply"));
  ASSERT_EQ(w.ran().size(), 4u);
  const fs::path seg = w.out / "bladder.seg.nrrd";
  const long erased = paint_in_slicer(seg, -1);
  ASSERT_LT(erased, 0);
  ASSERT_TRUE(io::lists_segments(seg));  // saved with Slicer's Segment0_* keys
  EXPECT_EQ(io::read_segments(seg).front().name, "bladder");
  expect_volume_follows_the_label(w, seg, erased);
}

TEST(EditRoundTrip, AMeshRefinedInGmshIsWhatTheSimulationReads) {
  const Workdir w("edit-msh", pipeline_yaml("bladder.nii.gz", "bladder.ply", true));
  ASSERT_EQ(w.ran().size(), 5u);
  const long triangles = w.report("mesh")["triangle_count"];
  refine_in_gmsh(w.out / "bladder.msh");
  const std::string saved = content_hash(w.out / "bladder.msh");
  EXPECT_EQ(status_of(w.file, w.dir).at("mesh").first, "edited");
  EXPECT_EQ(w.ran(), Ids{"simulate"});
  EXPECT_EQ(content_hash(w.out / "bladder.msh"), saved);
  const auto summary = nlohmann::json::parse(slurp(w.out / "sim/summary.json"));
  EXPECT_EQ(summary["triangles"].get<long>(), 4 * triangles);  // the refined wall
  const auto manifest = nlohmann::json::parse(slurp(w.out / ".vesica/simulate.manifest.json"));
  EXPECT_EQ(manifest["inputs"][0]["hash"], saved);
  // The .vtu beside it, for ParaView, followed the edit: the refined mesh, node for node.
  const io::VolumeMesh vtu = io::read_mesh_vtu(w.out / "bladder.vtu");
  const io::MshFile msh = io::read_msh(w.out / "bladder.msh");
  EXPECT_EQ(vtu.triangles.rows(), 4 * triangles);
  EXPECT_EQ(vtu.triangles, msh.mesh.triangles);
  ASSERT_EQ(vtu.nodes.rows(), msh.mesh.nodes.rows());
  EXPECT_LT((vtu.nodes - msh.mesh.nodes).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_EQ(vtu.fiber1.rows(), vtu.triangles.rows());  // recomputed, as for a new mesh
  EXPECT_EQ(w.ran(), Ids{});
}
