// The mesh files of vesica-mesh round-trip through vesica_io and are read the same way by
// independent readers: meshio (.msh, .vtu and every step of a .pvd series) and VTK's own
// reader (.vtu). The .msh keeps
// thickness and fibers as element data, and a mesh whose views no longer fit its nodes
// loses them with a note instead of giving wrong fibers.
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <fstream>
#include <sstream>

#include "OctahedronMesh.h"
#include "PythonReader.h"
#include "TestData.h"
#include "vesica/io/MshFile.h"
#include "vesica/io/PvdSeries.h"
#include "vesica/io/VtuFile.h"

namespace vesica::test {
namespace {

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// meshio's view of a mesh file: cell counts, the thickness data and physical names.
const char* kMeshioSummary = R"(
import json, sys, meshio
m = meshio.read(sys.argv[1] if len(sys.argv) > 1 else PATH)
out = {"points": [list(map(float, p)) for p in m.points],
       "triangles": sum(len(c.data) for c in m.cells if c.type == "triangle"),
       "tetra": sum(len(c.data) for c in m.cells if c.type == "tetra"),
       "names": sorted(m.field_data.keys())}
for name in ("thickness_mm", "region"):
    if name in m.cell_data:
        out[name] = [float(v) for block in m.cell_data[name] for v in block]
out["point_arrays"] = {k: [float(x) for x in v.ravel()[:3]] + [len(v)]
                       for k, v in m.point_data.items()}
out["field"] = {k: [float(x) for x in v.ravel()] for k, v in m.field_data.items()}
print(json.dumps(out))
)";

nlohmann::json meshio_summary(const std::filesystem::path& file) {
  std::string script = kMeshioSummary;
  script.replace(script.find("PATH"), 4, "'" + file.string() + "'");
  return run_python(script, file.parent_path());
}

TEST(MeshFiles, MshRoundTripKeepsOrderRegionsThicknessAndFibers) {
  const io::VolumeMesh m = octahedron_mesh();
  const auto dir = scratch_dir("io-msh-roundtrip");
  io::write_msh(m, dir / "b.msh");
  const io::MshFile back = io::read_msh(dir / "b.msh");
  EXPECT_TRUE(back.notes.empty());
  EXPECT_EQ(back.mesh.nodes, m.nodes);  // small integers: exact in 16 digits
  EXPECT_EQ(back.mesh.triangles, m.triangles);
  EXPECT_EQ(back.mesh.tri_region, m.tri_region);
  EXPECT_EQ(back.mesh.tets, m.tets);
  EXPECT_EQ(back.mesh.thickness_mm, m.thickness_mm);
  EXPECT_LT((back.mesh.fiber1 - m.fiber1).cwiseAbs().maxCoeff(), 1e-15);
  EXPECT_LT((back.mesh.fiber2 - m.fiber2).cwiseAbs().maxCoeff(), 1e-15);
  // Only the finished file is left in the folder.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(MeshFiles, MshIsReadAlikeByMeshio) {
  const io::VolumeMesh m = octahedron_mesh();
  const auto dir = scratch_dir("io-msh-meshio");
  io::write_msh(m, dir / "b.msh");
  const std::string text = read_text(dir / "b.msh");
  EXPECT_EQ(text.rfind("$MeshFormat\n4.1 0 8", 0), 0u);
  EXPECT_NE(text.find("2 1 \"wall\""), std::string::npos);
  EXPECT_NE(text.find("2 2 \"outlet\""), std::string::npos);
  EXPECT_NE(text.find("2 4 \"fixed\""), std::string::npos);
  EXPECT_NE(text.find("3 10 \"urine\""), std::string::npos);
  EXPECT_EQ(text.find("\"inlet\""), std::string::npos);  // empty groups are left out

  const nlohmann::json j = meshio_summary(dir / "b.msh");
  EXPECT_EQ(j["triangles"], 8);
  EXPECT_EQ(j["tetra"], 8);
  EXPECT_EQ(j["names"], nlohmann::json({"fixed", "outlet", "urine", "wall"}));
  ASSERT_TRUE(j.contains("thickness_mm")) << j.dump();
  const std::vector<double> thickness = j["thickness_mm"].get<std::vector<double>>();
  ASSERT_EQ(thickness.size(), 16u);  // triangles, then 0 on the tetrahedra
  for (int f = 0; f < 8; ++f) EXPECT_EQ(thickness[f], 2.5 + 0.25 * f);
  for (int t = 8; t < 16; ++t) EXPECT_EQ(thickness[t], 0.0);
  ASSERT_EQ(j["points"].size(), 7u);
  for (int i = 0; i < 7; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(j["points"][i][k].get<double>(), m.nodes(i, k));
}

TEST(MeshFiles, FibersThatNoLongerLieInTheirTrianglesAreDroppedWithANote) {
  io::VolumeMesh m = octahedron_mesh();
  m.nodes.col(2) *= 1.5;  // nodes moved (stretched along z), views of the old geometry kept
  const auto dir = scratch_dir("io-msh-stale-fibers");
  io::write_msh(m, dir / "b.msh");
  const io::MshFile back = io::read_msh(dir / "b.msh");
  EXPECT_EQ(back.mesh.fiber1.rows(), 0);
  EXPECT_EQ(back.mesh.thickness_mm, m.thickness_mm);  // a thickness does not depend on nodes
  ASSERT_EQ(back.notes.size(), 1u);
  EXPECT_NE(back.notes[0].find("fiber"), std::string::npos) << back.notes[0];
}

TEST(MeshFiles, VtuRoundTripAndContract) {
  const io::VolumeMesh m = octahedron_mesh();
  const auto dir = scratch_dir("io-vtu-roundtrip");
  io::write_mesh_vtu(m, dir / "b.vtu");
  const io::VolumeMesh back = io::read_mesh_vtu(dir / "b.vtu");
  EXPECT_EQ(back.nodes, m.nodes);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.tets, m.tets);
  EXPECT_EQ(back.tri_region, m.tri_region);
  EXPECT_EQ(back.thickness_mm, m.thickness_mm);
  EXPECT_EQ(back.fiber1, m.fiber1);
  EXPECT_EQ(back.fiber2, m.fiber2);

  vtkNew<vtkXMLUnstructuredGridReader> reader;
  reader->SetFileName((dir / "b.vtu").c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  vtkDataArray* unit = grid->GetFieldData()->GetArray("length_unit_m");
  ASSERT_NE(unit, nullptr);
  EXPECT_EQ(unit->GetComponent(0, 0), 1e-3);
  EXPECT_EQ(grid->GetFieldData()->GetAbstractArray("units"), nullptr);  // no String arrays
  auto* region = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("region"));
  ASSERT_NE(region, nullptr);
  EXPECT_EQ(region->GetValue(grid->GetNumberOfCells() - 1), 10);  // a tetrahedron
  EXPECT_NE(vtkDoubleArray::SafeDownCast(grid->GetCellData()->GetArray("thickness_mm")), nullptr);
  auto* fiber1 = vtkDoubleArray::SafeDownCast(grid->GetCellData()->GetArray("fiber1"));
  ASSERT_NE(fiber1, nullptr);
  EXPECT_EQ(fiber1->GetNumberOfComponents(), 3);
}

TEST(MeshFiles, SeriesListsItsStepsWithTimesAndTheirArrays) {
  const io::VolumeMesh m = octahedron_mesh();
  const auto dir = scratch_dir("io-pvd-series");
  io::PvdSeries series(dir, "series");
  for (int step = 0; step < 2; ++step) {
    io::VtuGrid frame;
    frame.points_mm = m.nodes * (1.0 + 0.1 * step);
    frame.triangles = m.triangles;
    io::VtuArray displacement{"displacement_mm", 3, {}, false};
    for (Eigen::Index i = 0; i < m.nodes.rows(); ++i)
      for (int k = 0; k < 3; ++k) displacement.values.push_back(0.1 * step * m.nodes(i, k));
    frame.point_data.push_back(displacement);
    frame.cell_data.push_back({"region", 1, std::vector<double>(8, 1.0), true});
    series.add_step(0.5 * step, frame);
  }
  series.finish();
  const auto steps = io::read_pvd(series.pvd_path());
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[1].first, 0.5);
  EXPECT_EQ(steps[1].second, "series/step_0001.vtu");
  const io::VtuGrid back = io::read_vtu(dir / steps[1].second);
  EXPECT_EQ(back.points_mm, m.nodes * 1.1);
  ASSERT_NE(back.point_array("displacement_mm"), nullptr);
  EXPECT_DOUBLE_EQ(back.point_array("displacement_mm")->values[0], 0.1 * 10.0);
  ASSERT_NE(back.cell_array("region"), nullptr);
  EXPECT_TRUE(back.cell_array("region")->integer);
}

// ParaView users and Python users open the same files: meshio (Debian's python3-meshio)
// reads the mesh .vtu and each step of a series, cell for cell.
TEST(MeshFiles, MeshioReadsTheMeshVtuAndEverySeriesStep) {
  const io::VolumeMesh m = octahedron_mesh();
  const auto dir = scratch_dir("io-vtu-meshio");
  io::write_mesh_vtu(m, dir / "b.vtu");
  const nlohmann::json j = meshio_summary(dir / "b.vtu");
  EXPECT_EQ(j.value("triangles", -1), m.triangles.rows());
  EXPECT_EQ(j.value("tetra", -1), m.tets.rows());
  ASSERT_TRUE(j.contains("thickness_mm"));
  EXPECT_EQ(j["thickness_mm"][0].get<double>(), m.thickness_mm(0));

  io::PvdSeries series(dir, "series");
  for (int step = 0; step < 3; ++step) {
    io::VtuGrid frame;
    frame.points_mm = m.nodes;
    frame.triangles = m.triangles;
    frame.point_data.push_back(
        {"displacement_mm", 3, std::vector<double>(m.nodes.size(), 0.5), false});
    frame.cell_data.push_back({"region", 1, std::vector<double>(m.triangles.rows(), 1.0), true});
    // The field arrays of a simulation's step, then its displacement: meshio once took the
    // one for the other when they were raw bytes.
    frame.field_data.push_back({"volume_ml", 1, {100.0 + step}, false});
    frame.field_data.push_back({"pdet_cmh2o", 1, {8.5}, false});
    series.add_step(2.0 * step, frame);
  }
  series.finish();
  for (const auto& [time_s, file] : io::read_pvd(series.pvd_path())) {
    const nlohmann::json s = meshio_summary(dir / file);
    EXPECT_EQ(s.value("triangles", -1), m.triangles.rows()) << file;
    ASSERT_TRUE(s.contains("region")) << file;
    EXPECT_EQ(s["region"][0].get<double>(), 1.0) << file;
    EXPECT_EQ(s["names"], nlohmann::json({"length_unit_m", "pdet_cmh2o", "time_s", "volume_ml"}))
        << file;
    EXPECT_EQ(s["field"]["length_unit_m"], nlohmann::json({1e-3})) << file;
    EXPECT_EQ(s["field"]["time_s"], nlohmann::json({time_s})) << file;
    EXPECT_EQ(s["point_arrays"]["displacement_mm"],
              nlohmann::json({0.5, 0.5, 0.5, static_cast<double>(m.nodes.rows())}))
        << file;
  }
}

}  // namespace
}  // namespace vesica::test
