// The only translation unit of simulate that includes VTK.
#include "vesica/simulate/MeshReader.h"

#include <map>
#include <tuple>

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {

vtkSmartPointer<vtkDataSet> read_dataset(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".vtu") {
    vtkNew<vtkXMLUnstructuredGridReader> r;
    if (!r->CanReadFile(path.c_str())) fail(path.string(), "is not a readable VTK .vtu file");
    r->SetFileName(path.c_str());
    r->Update();
    return r->GetOutput();
  }
  if (ext == ".vtp") {
    vtkNew<vtkXMLPolyDataReader> r;
    if (!r->CanReadFile(path.c_str())) fail(path.string(), "is not a readable VTK .vtp file");
    r->SetFileName(path.c_str());
    r->Update();
    return r->GetOutput();
  }
  if (ext == ".stl") {
    vtkNew<vtkSTLReader> r;
    r->SetFileName(path.c_str());
    r->MergingOn();
    r->Update();
    return r->GetOutput();
  }
  fail(path.string(), "has an unsupported extension '" + ext + "'",
       "give the .vtu or .msh from vesica-mesh, or a surface .vtp/.stl");
}

}  // namespace

WallModel read_wall(const std::filesystem::path& given, double default_thickness_m) {
  std::filesystem::path path = given;
  if (path.extension() == ".msh") path.replace_extension(".vtu");
  if (!std::filesystem::exists(path))
    fail(path.string(), "does not exist",
         given.extension() == ".msh" ? "vesica-mesh writes the .vtu beside the .msh" : "");
  const vtkSmartPointer<vtkDataSet> data = read_dataset(path);
  if (!data || data->GetNumberOfPoints() == 0) fail(path.string(), "holds no points");
  vtkCellData* cd = data->GetCellData();
  vtkDataArray* region = cd->GetArray("region");
  vtkDataArray* thickness = cd->GetArray("thickness_mm");
  vtkDataArray* fiber1 = cd->GetArray("fiber1");
  vtkDataArray* fiber2 = cd->GetArray("fiber2");

  WallModel wall;
  std::map<vtkIdType, int> node_of;  // compact numbering of the points triangles use
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    if (data->GetCellType(c) != VTK_TRIANGLE) continue;  // tets (urine), lines, vertices
    data->GetCellPoints(c, ids);
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) {
      const vtkIdType id = ids->GetId(k);
      auto it = node_of.find(id);
      if (it == node_of.end()) {
        double p[3];
        data->GetPoint(id, p);
        wall.nodes.emplace_back(units::m_from_mm(p[0]), units::m_from_mm(p[1]),
                                units::m_from_mm(p[2]));
        it = node_of.emplace(id, static_cast<int>(wall.nodes.size()) - 1).first;
      }
      t[k] = it->second;
    }
    wall.triangles.push_back(t);
    const int r = region ? static_cast<int>(region->GetTuple1(c)) : static_cast<int>(Region::Wall);
    if (r < 1 || r > 5)
      fail(path.string(), "triangle " + std::to_string(c) + " has region " + std::to_string(r) +
                              " (expected 1..5)");
    wall.region.push_back(r);
    const double h = thickness ? units::m_from_mm(thickness->GetTuple1(c)) : default_thickness_m;
    if (!(h > 0.0)) fail(path.string(), "triangle " + std::to_string(c) + " has thickness <= 0");
    wall.thickness.push_back(h);
    if (fiber1 && fiber2) {
      const double* a = fiber1->GetTuple3(c);
      Eigen::Vector3d f1(a[0], a[1], a[2]);
      const double* b = fiber2->GetTuple3(c);
      Eigen::Vector3d f2(b[0], b[1], b[2]);
      wall.fibers.push_back({f1, f2});
    }
  }
  if (wall.triangles.empty())
    fail(path.string(), "contains no triangles", "the wall must be a triangle surface");
  wall.fixed.assign(wall.nodes.size(), {false, false, false});
  wall.support.assign(wall.nodes.size(), false);
  check_closed_surface(wall, path.string());
  return wall;
}

}  // namespace vesica::simulate
