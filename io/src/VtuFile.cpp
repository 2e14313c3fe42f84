#include "vesica/io/VtuFile.h"

#include <cmath>

#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include "VtkErrors.h"
#include "VtkXmlCheck.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"
#include "vesica/core/SideOutputNames.h"

namespace vesica::io {
namespace {

constexpr const char* kLengthUnitArray = "length_unit_m";

vtkSmartPointer<vtkDataArray> to_vtk(const VtuArray& a, vtkIdType tuples, const std::string& file) {
  if (a.components < 1 || a.values.size() != static_cast<std::size_t>(tuples * a.components))
    fail(file, "array " + a.name + " has " + std::to_string(a.values.size()) + " values for " +
                   std::to_string(tuples) + " tuples of " + std::to_string(a.components));
  vtkSmartPointer<vtkDataArray> out;
  if (a.integer)
    out = vtkSmartPointer<vtkIntArray>::New();
  else
    out = vtkSmartPointer<vtkDoubleArray>::New();
  out->SetName(a.name.c_str());
  out->SetNumberOfComponents(a.components);
  out->SetNumberOfTuples(tuples);
  for (vtkIdType t = 0; t < tuples; ++t)
    for (int c = 0; c < a.components; ++c)
      out->SetComponent(t, c, a.values[static_cast<std::size_t>(t * a.components + c)]);
  return out;
}

vtkNew<vtkUnstructuredGrid> to_grid(const VtuGrid& g, const std::string& file) {
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(g.points_mm.rows());
  for (Eigen::Index i = 0; i < g.points_mm.rows(); ++i)
    points->SetPoint(i, g.points_mm(i, 0), g.points_mm(i, 1), g.points_mm(i, 2));
  grid->SetPoints(points);
  grid->Allocate(g.triangles.rows() + g.tets.rows());
  for (Eigen::Index t = 0; t < g.triangles.rows(); ++t) {
    const vtkIdType ids[3] = {g.triangles(t, 0), g.triangles(t, 1), g.triangles(t, 2)};
    grid->InsertNextCell(VTK_TRIANGLE, 3, ids);
  }
  for (Eigen::Index t = 0; t < g.tets.rows(); ++t) {
    const vtkIdType ids[4] = {g.tets(t, 0), g.tets(t, 1), g.tets(t, 2), g.tets(t, 3)};
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  for (const VtuArray& a : g.point_data)
    grid->GetPointData()->AddArray(to_vtk(a, g.points_mm.rows(), file));
  for (const VtuArray& a : g.cell_data)
    grid->GetCellData()->AddArray(to_vtk(a, g.triangles.rows() + g.tets.rows(), file));
  for (const VtuArray& a : g.field_data) grid->GetFieldData()->AddArray(to_vtk(a, 1, file));
  // The unit as a number, not a string: meshio's VTU reader stops at a String array.
  vtkNew<vtkDoubleArray> unit;
  unit->SetName(kLengthUnitArray);
  unit->InsertNextValue(1e-3);
  grid->GetFieldData()->AddArray(unit);
  return grid;
}

VtuArray from_vtk(vtkDataArray* a, const std::vector<vtkIdType>& order) {
  VtuArray out;
  out.name = a->GetName() ? a->GetName() : "";
  out.components = a->GetNumberOfComponents();
  out.integer = vtkIntArray::SafeDownCast(a) != nullptr;
  out.values.reserve(order.size() * static_cast<std::size_t>(out.components));
  for (vtkIdType id : order)
    for (int c = 0; c < out.components; ++c) out.values.push_back(a->GetComponent(id, c));
  return out;
}

const VtuArray* find(const std::vector<VtuArray>& arrays, const std::string& name) {
  for (const VtuArray& a : arrays)
    if (a.name == name) return &a;
  return nullptr;
}

// A cell array of the mesh file must have the width its name says; a "fiber1" of two
// components or a "thickness_mm" of three is a broken file, not a missing array.
const VtuArray* mesh_array(const VtuGrid& g, const char* name, int width, const std::string& file) {
  const VtuArray* a = g.cell_array(name);
  if (a && a->components != width)
    fail(file, std::string("cell array ") + name + " has " + std::to_string(a->components) +
                   " components, expected " + std::to_string(width));
  return a;
}

Eigen::MatrixXd triangle_rows(const VtuArray* a, Eigen::Index triangles) {
  if (!a) return Eigen::MatrixXd(0, 3);
  Eigen::MatrixXd rows(triangles, 3);
  for (Eigen::Index t = 0; t < triangles; ++t)
    for (int k = 0; k < 3; ++k) rows(t, k) = a->values[static_cast<std::size_t>(3 * t + k)];
  return rows;
}

VtuArray cell_vector(const char* name, const Eigen::MatrixXd& tri, Eigen::Index tets) {
  VtuArray a{name, 3, {}, false};
  for (Eigen::Index t = 0; t < tri.rows(); ++t)
    for (int k = 0; k < 3; ++k) a.values.push_back(tri(t, k));
  a.values.resize(a.values.size() + 3 * static_cast<std::size_t>(tets), 0.0);
  return a;
}

// Coordinates must be in mm: files of vesica say so with "length_unit_m" = 0.001; files
// written before that with the string "units" = "mm". A file with neither is taken as mm.
void check_length_unit(vtkUnstructuredGrid& grid, const std::string& file) {
  vtkFieldData* field = grid.GetFieldData();
  if (auto* units = vtkStringArray::SafeDownCast(field->GetAbstractArray("units"));
      units && units->GetNumberOfValues() > 0 && units->GetValue(0) != "mm")
    fail(file, "coordinates are in '" + units->GetValue(0) + "', expected mm");
  vtkDataArray* unit = field->GetArray(kLengthUnitArray);
  if (unit && unit->GetNumberOfTuples() > 0 && std::abs(unit->GetComponent(0, 0) - 1e-3) > 1e-12)
    fail(file, "coordinates are in units of " + std::to_string(unit->GetComponent(0, 0)) +
                   " m (field " + kLengthUnitArray + "), expected mm (0.001)");
}

}  // namespace

const VtuArray* VtuGrid::cell_array(const std::string& name) const {
  return find(cell_data, name);
}

const VtuArray* VtuGrid::point_array(const std::string& name) const {
  return find(point_data, name);
}

const VtuArray* VtuGrid::field_array(const std::string& name) const {
  return find(field_data, name);
}

void write_vtu(const VtuGrid& g, const std::filesystem::path& path,
               const VtuWriteOptions& options) {
  vtkNew<vtkUnstructuredGrid> grid = to_grid(g, path.string());
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetFileName(tmp.c_str());
    writer->SetInputData(grid);
    writer->SetDataModeToAppended();
    // Base64, not raw bytes: meshio's reader of raw appended data finds each array by its
    // offset after renumbering earlier ones, and takes the wrong array when the numbers meet.
    writer->EncodeAppendedDataOn();
    if (options.compress)
      writer->SetCompressorTypeToZLib();
    else
      writer->SetCompressorTypeToNone();
    const auto errors = detail::watch_errors(writer);
    if (writer->Write() != 1 || errors->any() || writer->GetErrorCode() != vtkErrorCode::NoError)
      fail(path.string(), "could not write the VTU file: " +
                              detail::vtk_write_error(*errors, writer->GetErrorCode()));
  });
}

VtuGrid read_vtu(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) fail(name, "file not found");
  detail::check_vtk_xml_counts(path);  // a regular file of bounded size, counts that fit
  vtkNew<vtkXMLUnstructuredGridReader> reader;
  if (!reader->CanReadFile(name.c_str())) fail(name, "not a VTK XML unstructured grid");
  reader->SetFileName(name.c_str());
  const auto errors = detail::watch_errors(reader);
  detail::update_reader(*reader, name);
  if (errors->any())
    fail(name, "cannot read the VTU file: " + detail::vtk_message_line(errors->message()));
  vtkUnstructuredGrid* grid = reader->GetOutput();
  check_length_unit(*grid, name);

  VtuGrid g;
  g.points_mm.resize(grid->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < grid->GetNumberOfPoints(); ++i) {
    double p[3];
    grid->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(name, "point " + std::to_string(i) + " has a coordinate that is not finite");
    g.points_mm.row(i) << p[0], p[1], p[2];
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
  vtkNew<vtkIdList> ids;
  g.triangles.resize(static_cast<Eigen::Index>(tri_cells.size()), 3);
  for (std::size_t t = 0; t < tri_cells.size(); ++t) {
    grid->GetCellPoints(tri_cells[t], ids);
    for (int k = 0; k < 3; ++k) g.triangles(static_cast<Eigen::Index>(t), k) = ids->GetId(k);
  }
  g.tets.resize(static_cast<Eigen::Index>(tet_cells.size()), 4);
  for (std::size_t t = 0; t < tet_cells.size(); ++t) {
    grid->GetCellPoints(tet_cells[t], ids);
    for (int k = 0; k < 4; ++k) g.tets(static_cast<Eigen::Index>(t), k) = ids->GetId(k);
  }
  std::vector<vtkIdType> cell_order = tri_cells;
  cell_order.insert(cell_order.end(), tet_cells.begin(), tet_cells.end());
  std::vector<vtkIdType> point_order(static_cast<std::size_t>(grid->GetNumberOfPoints()));
  for (std::size_t i = 0; i < point_order.size(); ++i) point_order[i] = static_cast<vtkIdType>(i);
  for (int a = 0; a < grid->GetCellData()->GetNumberOfArrays(); ++a)
    if (vtkDataArray* array = grid->GetCellData()->GetArray(a))
      g.cell_data.push_back(from_vtk(array, cell_order));
  for (int a = 0; a < grid->GetPointData()->GetNumberOfArrays(); ++a)
    if (vtkDataArray* array = grid->GetPointData()->GetArray(a))
      g.point_data.push_back(from_vtk(array, point_order));
  // GetArray gives the numeric arrays only; the unit, checked above, is the file's, not data.
  vtkFieldData* field = grid->GetFieldData();
  for (int a = 0; a < field->GetNumberOfArrays(); ++a)
    if (vtkDataArray* array = field->GetArray(a); array && array->GetNumberOfTuples() > 0 &&
                                                  std::string(kLengthUnitArray) != array->GetName())
      g.field_data.push_back(from_vtk(array, {0}));
  return g;
}

void write_mesh_vtu(const VolumeMesh& mesh, const std::filesystem::path& path) {
  const Eigen::Index m = mesh.triangles.rows(), k = mesh.tets.rows();
  VtuGrid g;
  g.points_mm = mesh.nodes;
  g.triangles = mesh.triangles;
  g.tets = mesh.tets;
  VtuArray region{"region", 1, {}, true};
  VtuArray thickness{"thickness_mm", 1, {}, false};
  for (Eigen::Index t = 0; t < m; ++t) {
    region.values.push_back(mesh.tri_region(t));
    thickness.values.push_back(mesh.thickness_mm.size() == m ? mesh.thickness_mm(t) : 0.0);
  }
  region.values.resize(static_cast<std::size_t>(m + k), kUrineVolumeTag);
  thickness.values.resize(static_cast<std::size_t>(m + k), 0.0);
  g.cell_data = {region, thickness};
  if (mesh.thickness_mm.size() != m) g.cell_data.pop_back();
  if (mesh.fiber1.rows() == m && mesh.fiber2.rows() == m) {
    g.cell_data.push_back(cell_vector("fiber1", mesh.fiber1, k));
    g.cell_data.push_back(cell_vector("fiber2", mesh.fiber2, k));
  }
  write_vtu(g, path);
}

VolumeMesh read_mesh_vtu(const std::filesystem::path& path) {
  const std::string file = path.string();
  const VtuGrid g = read_vtu(path);
  const Eigen::Index m = g.triangles.rows();
  VolumeMesh mesh;
  mesh.nodes = g.points_mm;
  mesh.triangles = g.triangles;
  mesh.tets = g.tets;
  const VtuArray* region = mesh_array(g, "region", 1, file);
  mesh.tri_region = Eigen::VectorXi::Constant(m, static_cast<int>(Region::Wall));
  if (region)
    for (Eigen::Index t = 0; t < m; ++t) {
      const double code = region->values[static_cast<std::size_t>(t)];
      if (!(code >= 0 && code <= kUrineVolumeTag) || static_cast<int>(code) != code)
        fail(file, "triangle " + std::to_string(t) + " has region " + std::to_string(code),
             "codes are wall=1, outlet=2, inlet=3, fixed=4, support=5");
      mesh.tri_region(t) = static_cast<int>(code);
    }
  if (const VtuArray* h = mesh_array(g, "thickness_mm", 1, file)) {
    mesh.thickness_mm.resize(m);
    for (Eigen::Index t = 0; t < m; ++t)
      mesh.thickness_mm(t) = h->values[static_cast<std::size_t>(t)];
  }
  mesh.fiber1 = triangle_rows(mesh_array(g, "fiber1", 3, file), m);
  mesh.fiber2 = triangle_rows(mesh_array(g, "fiber2", 3, file), m);
  if (mesh.fiber1.rows() != mesh.fiber2.rows())
    fail(file, "has one of the cell arrays fiber1 and fiber2 without the other");
  return mesh;
}

std::filesystem::path vtu_beside(const std::filesystem::path& msh_path) {
  return vtu_beside_msh(msh_path.string());
}

}  // namespace vesica::io
