// Surfaces in formats without cell data keep their region tags through the JSON sidecar
// that vesica-surface writes beside them; duplicate points are joined.
#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "TestData.h"
#include "TestSurfaces.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/mesh/SurfaceDefects.h"
#include "vesica/mesh/SurfaceReader.h"

using namespace vesica;
using namespace vesica::mesh;
namespace fs = std::filesystem;

namespace {

// STL stores every triangle with its own three corners: nothing is shared in the file.
void write_stl_with_sidecar(const SurfaceMesh& s, const fs::path& path, std::size_t tag_count) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k) {
      const Eigen::RowVector3d p = s.points.row(s.triangles(t, k));
      ids[k] = points->InsertNextPoint(p(0), p(1), p(2));
    }
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetPolys(polys);
  vtkNew<vtkSTLWriter> writer;
  writer->SetFileName(path.c_str());
  writer->SetInputData(pd);
  writer->SetFileTypeToBinary();
  writer->Write();
  std::vector<int> tags(s.region.data(), s.region.data() + s.region.size());
  tags.resize(tag_count, 1);
  std::ofstream(path.string() + ".regions.json")
      << nlohmann::json{{"units", "mm"}, {"region", tags}}.dump();
}

SurfaceMesh tagged_sphere() {
  SurfaceMesh s = test::icosphere(20.0, 2);
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t)
    if (s.points(s.triangles(t, 0), 2) > 17.0) s.region(t) = static_cast<int>(Region::Outlet);
  return s;
}

}  // namespace

TEST(SurfaceReader, StlWithSidecarIsJoinedAndKeepsItsRegions) {
  const fs::path dir = test::scratch_dir("mesh-reader-stl");
  const SurfaceMesh s = tagged_sphere();
  write_stl_with_sidecar(s, dir / "s.stl", s.triangles.rows());
  const SurfaceMesh back = read_surface(dir / "s.stl");
  EXPECT_EQ(back.points.rows(), s.points.rows());  // shared corners joined again
  EXPECT_EQ(back.triangles.rows(), s.triangles.rows());
  EXPECT_EQ(back.region, s.region);
  EXPECT_TRUE(find_surface_defects(back).ok());
}

TEST(SurfaceReader, SidecarWithWrongCountIsAnError) {
  const fs::path dir = test::scratch_dir("mesh-reader-stl-bad");
  const SurfaceMesh s = tagged_sphere();
  write_stl_with_sidecar(s, dir / "s.stl", 7);
  EXPECT_THROW(read_surface(dir / "s.stl"), Error);
}
