// The .msh and .vtu files follow the shared contract: physical groups named after the
// regions, "urine" for the tetrahedra, and a .vtu with region/thickness/fibers in mm.
#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <fstream>
#include <sstream>

#include "TestData.h"
#include "TestSurfaces.h"
#include "vesica/mesh/BladderMesh.h"
#include "vesica/mesh/MeshFiles.h"

using namespace vesica;
using namespace vesica::mesh;

namespace {

VolumeMesh tagged_sphere_mesh() {
  SurfaceMesh s = test::icosphere(20.0, 2);
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    const double z = s.points(s.triangles(t, 0), 2);
    if (z > 17.0) s.region(t) = static_cast<int>(Region::Outlet);
    if (z < -17.0) s.region(t) = static_cast<int>(Region::Fixed);
  }
  return build_bladder_mesh(s, MembraneOptions{}, CavityOptions{}, "sphere");
}

std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Number of elements of a Gmsh type in a .msh 4.1 ASCII file ($Elements blocks).
long count_msh_elements(const std::string& text, int type) {
  std::istringstream in(text.substr(text.find("$Elements")));
  std::string line;
  std::getline(in, line);
  long blocks, total, lo, hi;
  in >> blocks >> total >> lo >> hi;
  long count = 0;
  for (long b = 0; b < blocks; ++b) {
    int dim, tag, element_type;
    long n;
    in >> dim >> tag >> element_type >> n;
    std::getline(in, line);
    for (long i = 0; i < n; ++i) std::getline(in, line);
    if (element_type == type) count += n;
  }
  return count;
}

}  // namespace

TEST(MeshFiles, MshHasPhysicalGroupsPerRegionAndUrine) {
  const VolumeMesh m = tagged_sphere_mesh();
  const auto dir = test::scratch_dir("mesh-files-msh");
  write_msh(m, dir / "b.msh");
  const std::string text = read_text(dir / "b.msh");
  EXPECT_EQ(text.rfind("$MeshFormat\n4.1 0 8", 0), 0u);
  EXPECT_NE(text.find("2 1 \"wall\""), std::string::npos);
  EXPECT_NE(text.find("2 2 \"outlet\""), std::string::npos);
  EXPECT_NE(text.find("2 4 \"fixed\""), std::string::npos);
  EXPECT_NE(text.find("3 10 \"urine\""), std::string::npos);
  EXPECT_EQ(text.find("\"inlet\""), std::string::npos);  // empty groups are left out
  EXPECT_EQ(count_msh_elements(text, 2), m.triangles.rows());
  EXPECT_EQ(count_msh_elements(text, 4), m.tets.rows());
  // Only the finished file is left in the folder.
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
}

TEST(MeshFiles, VtuRoundTripAndContract) {
  const VolumeMesh m = tagged_sphere_mesh();
  const auto dir = test::scratch_dir("mesh-files-vtu");
  write_vtu(m, dir / "b.vtu");
  const VolumeMesh back = read_vtu(dir / "b.vtu");
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
  auto* units = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("units"));
  ASSERT_NE(units, nullptr);
  EXPECT_EQ(units->GetValue(0), "mm");
  auto* region = vtkIntArray::SafeDownCast(grid->GetCellData()->GetArray("region"));
  ASSERT_NE(region, nullptr);
  EXPECT_EQ(region->GetValue(grid->GetNumberOfCells() - 1), 10);  // a tetrahedron
  EXPECT_NE(vtkDoubleArray::SafeDownCast(grid->GetCellData()->GetArray("thickness_mm")), nullptr);
  auto* fiber1 = vtkDoubleArray::SafeDownCast(grid->GetCellData()->GetArray("fiber1"));
  ASSERT_NE(fiber1, nullptr);
  EXPECT_EQ(fiber1->GetNumberOfComponents(), 3);
}
