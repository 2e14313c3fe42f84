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

// The compact node numbering of the simulation: points in the order the triangles first
// use them (the wall), so that read_wall and read_urine number the wall alike.
std::map<vtkIdType, int> wall_numbering(vtkDataSet* data) {
  std::map<vtkIdType, int> node_of;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    if (data->GetCellType(c) != VTK_TRIANGLE) continue;
    data->GetCellPoints(c, ids);
    for (int k = 0; k < 3; ++k)
      node_of.try_emplace(ids->GetId(k), static_cast<int>(node_of.size()));
  }
  return node_of;
}

Eigen::Vector3d point_m(vtkDataSet* data, vtkIdType id) {
  double p[3];
  data->GetPoint(id, p);
  return {units::m_from_mm(p[0]), units::m_from_mm(p[1]), units::m_from_mm(p[2])};
}

std::filesystem::path vtu_of(const std::filesystem::path& given) {
  std::filesystem::path path = given;
  if (path.extension() == ".msh") path.replace_extension(".vtu");
  if (!std::filesystem::exists(path))
    fail(path.string(), "does not exist",
         given.extension() == ".msh" ? "vesica-mesh writes the .vtu beside the .msh" : "");
  return path;
}

}  // namespace

fluid::FluidMesh read_urine(const std::filesystem::path& given) {
  const std::filesystem::path path = vtu_of(given);
  if (path.extension() != ".vtu")
    fail(path.string(), "holds no tetrahedra", "level 2 needs the .vtu of vesica-mesh --fluid");
  const vtkSmartPointer<vtkDataSet> data = read_dataset(path);
  if (!data || data->GetNumberOfPoints() == 0) fail(path.string(), "holds no points");
  std::map<vtkIdType, int> node_of = wall_numbering(data);
  fluid::FluidMesh mesh;
  mesh.nodes.resize(node_of.size());
  for (const auto& [id, node] : node_of) mesh.nodes[node] = point_m(data, id);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    if (data->GetCellType(c) != VTK_TETRA) continue;
    data->GetCellPoints(c, ids);
    std::array<int, 4> t;
    for (int k = 0; k < 4; ++k) {
      auto [it, added] = node_of.try_emplace(ids->GetId(k), static_cast<int>(node_of.size()));
      if (added) mesh.nodes.push_back(point_m(data, it->first));
      t[k] = it->second;
    }
    mesh.tets.push_back(t);
  }
  if (mesh.tets.empty())
    fail(path.string(), "holds no tetrahedra", "mesh it with vesica-mesh --fluid for level 2");
  return mesh;
}

WallModel read_wall(const std::filesystem::path& given, double default_thickness_m) {
  const std::filesystem::path path = vtu_of(given);
  const vtkSmartPointer<vtkDataSet> data = read_dataset(path);
  if (!data || data->GetNumberOfPoints() == 0) fail(path.string(), "holds no points");
  vtkCellData* cd = data->GetCellData();
  vtkDataArray* region = cd->GetArray("region");
  vtkDataArray* thickness = cd->GetArray("thickness_mm");
  vtkDataArray* fiber1 = cd->GetArray("fiber1");
  vtkDataArray* fiber2 = cd->GetArray("fiber2");

  WallModel wall;
  const std::map<vtkIdType, int> node_of = wall_numbering(data);
  wall.nodes.resize(node_of.size());
  for (const auto& [id, node] : node_of) wall.nodes[node] = point_m(data, id);
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c) {
    if (data->GetCellType(c) != VTK_TRIANGLE) continue;  // tets (urine), lines, vertices
    data->GetCellPoints(c, ids);
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k) t[k] = node_of.at(ids->GetId(k));
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
