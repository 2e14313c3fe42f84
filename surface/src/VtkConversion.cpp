#include "vesica/surface/VtkConversion.h"

#include <vector>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include "vesica/surface/SurfaceIO.h"

namespace vesica::surface {

vtkSmartPointer<vtkPolyData> to_polydata(const TriangleSurface& surface) {
  return io::surface_polydata(to_tagged(surface));
}

TriangleSurface from_polydata(vtkPolyData* input) {
  auto triangulate = vtkSmartPointer<vtkTriangleFilter>::New();
  triangulate->SetInputData(input);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  triangulate->Update();
  vtkPolyData* poly = triangulate->GetOutput();

  // Renumber the points that triangles use, in their original order.
  std::vector<Eigen::Index> new_index(poly->GetNumberOfPoints(), -1);
  auto cells = poly->GetPolys();
  auto ids = vtkSmartPointer<vtkIdList>::New();
  std::vector<int> corners;
  for (cells->InitTraversal(); cells->GetNextCell(ids);)
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) corners.push_back(ids->GetId(k));
  for (int c : corners) new_index[c] = 0;
  Eigen::Index n = 0;
  for (auto& i : new_index)
    if (i == 0) i = n++;

  TriangleSurface out;
  out.V.resize(n, 3);
  for (vtkIdType p = 0; p < poly->GetNumberOfPoints(); ++p)
    if (new_index[p] >= 0) {
      double x[3];
      poly->GetPoint(p, x);
      out.V.row(new_index[p]) << x[0], x[1], x[2];
    }
  out.F.resize(static_cast<Eigen::Index>(corners.size() / 3), 3);
  for (std::size_t c = 0; c < corners.size(); ++c)
    out.F(c / 3, c % 3) = static_cast<int>(new_index[corners[c]]);

  // Polygon cells come after vertices and lines in VTK's cell numbering.
  if (vtkDataArray* region = poly->GetCellData()->GetArray("region")) {
    const vtkIdType first = poly->GetNumberOfVerts() + poly->GetNumberOfLines();
    out.region.resize(out.F.rows());
    for (Eigen::Index f = 0; f < out.F.rows(); ++f)
      out.region(f) = static_cast<int>(region->GetTuple1(first + f));
  }
  return out;
}

}  // namespace vesica::surface
