// vesica-mesh as a user runs it: outputs and report on a good surface; on a bad one a
// single error line listing the defects, exit 1 and nothing written; never raw gmsh log.
#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "MeshAcceptance.h"
#include "TestData.h"
#include "TestSurfaces.h"
#include "vesica/core/Units.h"

using namespace vesica;
namespace fs = std::filesystem;

namespace {

void write_vtp(const mesh::SurfaceMesh& s, const fs::path& path) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();  // the volume check is to 1e-9
  for (Eigen::Index i = 0; i < s.points.rows(); ++i)
    points->InsertNextPoint(s.points(i, 0), s.points(i, 1), s.points(i, 2));
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> region;
  region->SetName("region");
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    const vtkIdType ids[3] = {s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)};
    polys->InsertNextCell(3, ids);
    region->InsertNextValue(s.region(t));
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetPolys(polys);
  pd->GetCellData()->AddArray(region);
  vtkNew<vtkStringArray> units;
  units->SetName("units");
  units->InsertNextValue("mm");
  pd->GetFieldData()->AddArray(units);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(pd);
  writer->Write();
}

struct CliRun {
  int exit_code;
  std::string err;
  std::string out;
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

CliRun run_mesh(const std::string& args, const fs::path& dir) {
  const fs::path err = dir / "stderr.txt", out = dir / "stdout.txt";
  const std::string cmd = (test::bin_dir() / "vesica-mesh").string() + " " + args + " 2> " +
                          err.string() + " > " + out.string();
  const int status = std::system(cmd.c_str());
  CliRun run{WEXITSTATUS(status), slurp(err), slurp(out)};
  fs::remove(err);
  fs::remove(out);
  return run;
}

}  // namespace

TEST(MeshCli, WritesMshVtuAndReport) {
  const fs::path dir = test::scratch_dir("mesh-cli-ok");
  mesh::SurfaceMesh sphere = test::icosphere(30.0, 3);
  for (Eigen::Index t = 0; t < sphere.triangles.rows(); ++t)
    if (sphere.points(sphere.triangles(t, 0), 2) < -27.0) sphere.region(t) = 4;
  write_vtp(sphere, dir / "s.vtp");
  const CliRun r = run_mesh((dir / "s.vtp").string() + " -o " + (dir / "out/b.msh").string() +
                                " --fluid --thickness-by-region fixed=4.5 --report " +
                                (dir / "out/mesh.json").string(),
                            dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("Info"), std::string::npos) << r.err;  // gmsh stays quiet
  EXPECT_TRUE(fs::exists(dir / "out/b.msh"));
  EXPECT_TRUE(fs::exists(dir / "out/b.vtu"));
  std::ifstream in(dir / "out/mesh.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["triangle_count"], sphere.triangles.rows());
  EXPECT_GT(j["tetrahedron_count"].get<long>(), 1000);
  const double expected_ml =
      units::ml_from_mm3(test::divergence_volume_mm3(sphere.points, sphere.triangles));
  EXPECT_NEAR(j["enclosed_volume_ml"].get<double>(), expected_ml, 1e-9 * expected_ml);
  EXPECT_NEAR(j["tetrahedra_volume_ml"].get<double>(), expected_ml, 1e-9 * expected_ml);
  EXPECT_GT(j["region_triangle_counts"]["fixed"].get<long>(), 0);
  EXPECT_GE(j["quality"]["tet_min_dihedral_deg"].get<double>(), 5.0);
}

TEST(MeshCli, JsonPrintsOnlyTheSummary) {
  const fs::path dir = test::scratch_dir("mesh-cli-json");
  write_vtp(test::icosphere(20.0, 2), dir / "s.vtp");
  const CliRun r = run_mesh((dir / "s.vtp").string() + " -o " + (dir / "b.msh").string() +
                                " --fluid --json --fiber-direction long-axis",
                            dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");                         // neither our log nor gmsh's
  const auto j = nlohmann::json::parse(r.out);  // throws if anything else is on stdout
  EXPECT_EQ(j["triangle_count"], 320);
  EXPECT_GT(j["tetrahedron_count"].get<long>(), 0);
}

TEST(MeshCli, OpenSurfaceIsRefusedWithItsDefects) {
  const fs::path dir = test::scratch_dir("mesh-cli-open");
  mesh::SurfaceMesh sphere = test::icosphere(30.0, 2);
  sphere.triangles = sphere.triangles.bottomRows(sphere.triangles.rows() - 2).eval();
  sphere.region = sphere.region.tail(sphere.region.size() - 2).eval();
  write_vtp(sphere, dir / "open.vtp");
  const CliRun r =
      run_mesh((dir / "open.vtp").string() + " -o " + (dir / "b.msh").string() + " --fluid", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("open.vtp"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("boundary edges"), std::string::npos) << r.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 1);  // only the input
}

TEST(MeshCli, SelfIntersectingSurfaceIsRefused) {
  const fs::path dir = test::scratch_dir("mesh-cli-self");
  mesh::SurfaceMesh sphere = test::icosphere(30.0, 2);
  // Push one node far through the opposite side of the sphere.
  sphere.points.row(0) *= -1.6;
  write_vtp(sphere, dir / "self.vtp");
  const CliRun r =
      run_mesh((dir / "self.vtp").string() + " -o " + (dir / "b.msh").string() + " --fluid", dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("self-intersecting"), std::string::npos) << r.err;
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 1);
}

TEST(MeshCli, MissingFileAndBadOptions) {
  const fs::path dir = test::scratch_dir("mesh-cli-usage");
  EXPECT_EQ(
      run_mesh((dir / "none.vtp").string() + " -o " + (dir / "b.msh").string(), dir).exit_code, 1);
  write_vtp(test::icosphere(10.0, 1), dir / "s.vtp");
  EXPECT_EQ(run_mesh((dir / "s.vtp").string() + " -o " + (dir / "b.vtk").string(), dir).exit_code,
            2);
  EXPECT_EQ(run_mesh((dir / "s.vtp").string() + " -o " + (dir / "b.msh").string() +
                         " --thickness-by-region bottom=3",
                     dir)
                .exit_code,
            2);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir), {}), 1);
}
