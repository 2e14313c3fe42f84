// Writes the benchmark surface: an icosphere of 5,120 triangles stretched into a
// bladder-like ellipsoid (semi-axes 45, 40, 50 mm, about 377 ml), as a .vtp in mm.
#include <vtkCellArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <cstdio>

#include "TestSurfaces.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: bench_mesh_surface OUT.vtp\n");
    return 2;
  }
  vesica::mesh::SurfaceMesh s = vesica::test::icosphere(1.0, 4);
  s.points = s.points * Eigen::Vector3d(45.0, 40.0, 50.0).asDiagonal();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (Eigen::Index i = 0; i < s.points.rows(); ++i)
    points->InsertNextPoint(s.points(i, 0), s.points(i, 1), s.points(i, 2));
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index t = 0; t < s.triangles.rows(); ++t) {
    const vtkIdType ids[3] = {s.triangles(t, 0), s.triangles(t, 1), s.triangles(t, 2)};
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> pd;
  pd->SetPoints(points);
  pd->SetPolys(polys);
  vtkNew<vtkStringArray> units;
  units->SetName("units");
  units->InsertNextValue("mm");
  pd->GetFieldData()->AddArray(units);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(argv[1]);
  writer->SetInputData(pd);
  return writer->Write() == 1 ? 0 : 1;
}
