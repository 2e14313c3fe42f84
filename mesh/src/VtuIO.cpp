#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <vector>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/mesh/MeshFiles.h"

namespace vesica::mesh {

namespace {

vtkNew<vtkDoubleArray> vector_array(const char* name, const Eigen::MatrixXd& tri_values,
                                    Eigen::Index tet_count) {
  vtkNew<vtkDoubleArray> a;
  a->SetName(name);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(tri_values.rows() + tet_count);
  for (Eigen::Index t = 0; t < tri_values.rows(); ++t)
    a->SetTuple3(t, tri_values(t, 0), tri_values(t, 1), tri_values(t, 2));
  for (Eigen::Index t = 0; t < tet_count; ++t) a->SetTuple3(tri_values.rows() + t, 0, 0, 0);
  return a;
}

vtkNew<vtkUnstructuredGrid> to_grid(const VolumeMesh& mesh) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(mesh.nodes.rows());
  for (Eigen::Index i = 0; i < mesh.nodes.rows(); ++i)
    points->SetPoint(i, mesh.nodes(i, 0), mesh.nodes(i, 1), mesh.nodes(i, 2));
  grid->SetPoints(points);
  const Eigen::Index m = mesh.triangles.rows(), k = mesh.tets.rows();
  grid->Allocate(m + k);
  vtkNew<vtkIntArray> region;
  region->SetName("region");
  vtkNew<vtkDoubleArray> thickness;
  thickness->SetName("thickness_mm");
  for (Eigen::Index t = 0; t < m; ++t) {
    const vtkIdType ids[3] = {mesh.triangles(t, 0), mesh.triangles(t, 1), mesh.triangles(t, 2)};
    grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
    region->InsertNextValue(mesh.tri_region(t));
    thickness->InsertNextValue(mesh.thickness_mm(t));
  }
  for (Eigen::Index t = 0; t < k; ++t) {
    const vtkIdType ids[4] = {mesh.tets(t, 0), mesh.tets(t, 1), mesh.tets(t, 2), mesh.tets(t, 3)};
    grid->InsertNextCell(VTK_TETRA, 4, ids);
    region->InsertNextValue(kUrineVolumeTag);
    thickness->InsertNextValue(0.0);
  }
  grid->GetCellData()->AddArray(region);
  grid->GetCellData()->AddArray(thickness);
  grid->GetCellData()->AddArray(vector_array("fiber1", mesh.fiber1, k));
  grid->GetCellData()->AddArray(vector_array("fiber2", mesh.fiber2, k));
  vtkNew<vtkStringArray> units;
  units->SetName("units");
  units->InsertNextValue("mm");
  grid->GetFieldData()->AddArray(units);
  return grid;
}

}  // namespace

std::filesystem::path vtu_beside(const std::filesystem::path& msh_path) {
  return msh_path.parent_path() / (msh_path.stem().string() + ".vtu");
}

void write_vtu(const VolumeMesh& mesh, const std::filesystem::path& path) {
  vtkNew<vtkUnstructuredGrid> grid = to_grid(mesh);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    writer->SetCompressorTypeToZLib();
    if (writer->Write() != 1) fail(path.string(), "could not write the VTU file");
  });
}

VolumeMesh read_vtu(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) fail(name, "file not found");
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(name.c_str())) fail(name, "not a VTK XML unstructured grid");
  reader->SetFileName(name.c_str());
  reader->Update();
  vtkUnstructuredGrid* grid = reader->GetOutput();
  auto* units = vtkStringArray::SafeDownCast(grid->GetFieldData()->GetAbstractArray("units"));
  if (units && units->GetNumberOfValues() > 0 && units->GetValue(0) != "mm")
    fail(name, "coordinates are in '" + units->GetValue(0) + "', expected mm");

  VolumeMesh mesh;
  mesh.nodes.resize(grid->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    mesh.nodes.row(i) << p[0], p[1], p[2];
  }
  std::vector<vtkIdType> tri_cells, tet_cells;
  for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c) {
    const int type = grid->GetCellType(c);
    if (type == VTK_TRIANGLE)
      tri_cells.push_back(c);
    else if (type == VTK_TETRA)
      tet_cells.push_back(c);
    else
      fail(name, "cell " + std::to_string(c) + " is neither a triangle nor a tetrahedron");
  }
  vtkDataArray* region = grid->GetCellData()->GetArray("region");
  vtkDataArray* thickness = grid->GetCellData()->GetArray("thickness_mm");
  vtkDataArray* fiber1 = grid->GetCellData()->GetArray("fiber1");
  vtkDataArray* fiber2 = grid->GetCellData()->GetArray("fiber2");
  const auto m = static_cast<Eigen::Index>(tri_cells.size());
  mesh.triangles.resize(m, 3);
  mesh.tri_region.resize(m);
  mesh.thickness_mm.resize(m);
  mesh.fiber1 = Eigen::MatrixXd::Zero(m, 3);
  mesh.fiber2 = Eigen::MatrixXd::Zero(m, 3);
  vtkNew<vtkIdList> ids;
  for (Eigen::Index t = 0; t < m; ++t) {
    const vtkIdType c = tri_cells[t];
    grid->GetCellPoints(c, ids);
    for (int k = 0; k < 3; ++k) mesh.triangles(t, k) = static_cast<int>(ids->GetId(k));
    mesh.tri_region(t) =
        region ? static_cast<int>(region->GetComponent(c, 0)) : static_cast<int>(Region::Wall);
    mesh.thickness_mm(t) = thickness ? thickness->GetComponent(c, 0) : 3.0;
    for (int k = 0; k < 3 && fiber1 && fiber2; ++k) {
      mesh.fiber1(t, k) = fiber1->GetComponent(c, k);
      mesh.fiber2(t, k) = fiber2->GetComponent(c, k);
    }
  }
  mesh.tets.resize(static_cast<Eigen::Index>(tet_cells.size()), 4);
  for (std::size_t t = 0; t < tet_cells.size(); ++t) {
    grid->GetCellPoints(tet_cells[t], ids);
    for (int k = 0; k < 4; ++k)
      mesh.tets(static_cast<Eigen::Index>(t), k) = static_cast<int>(ids->GetId(k));
  }
  return mesh;
}

}  // namespace vesica::mesh
