#include "vesica/compare/report/UrineSection.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <vtkCellType.h>
#include <vtkCutter.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnstructuredGrid.h>

#include "vesica/core/Error.h"
#include "vesica/io/VtuFile.h"

namespace vesica::compare {
namespace {

namespace fs = std::filesystem;

Eigen::Vector3d field_vector(const io::VtuGrid& g, const char* name, const fs::path& vtu) {
  const io::VtuArray* a = g.field_array(name);
  if (!a || a->components != 3 || a->values.size() < 3)
    fail(vtu.string(), std::string("has no field data ") + name + " (not a level-2 fluid frame)");
  const Eigen::Vector3d v(a->values[0], a->values[1], a->values[2]);
  if (!v.allFinite()) fail(vtu.string(), std::string(name) + " is not finite");
  return v;
}

// The plane's axes: `along` the outlet axis, `normal` LPS x made ⟂ to it (y where the
// axis runs along x), `across` completing the frame.
void set_plane(UrineSection& s, const io::VtuGrid& g, const fs::path& vtu) {
  s.origin = field_vector(g, "outlet_centroid_mm", vtu);
  const Eigen::Vector3d axis = field_vector(g, "outlet_axis", vtu);
  if (axis.norm() == 0.0) fail(vtu.string(), "outlet_axis is zero");
  s.along = axis.normalized();
  Eigen::Vector3d n = Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitX().dot(s.along) * s.along;
  if (n.norm() < 1e-3)
    n = Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitY().dot(s.along) * s.along;
  s.normal = n.normalized();
  s.across = s.normal.cross(s.along);
}

// The frame's tetrahedra and velocity as VTK's grid, for its cutter. The file is read by
// io::read_vtu, which checks it (header, unit, cell types, finite points) before VTK's
// filters see it.
vtkSmartPointer<vtkUnstructuredGrid> tet_grid(const io::VtuGrid& g, const io::VtuArray& u) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();  // the cutter's points keep the input's precision
  points->SetNumberOfPoints(g.points_mm.rows());
  for (Eigen::Index i = 0; i < g.points_mm.rows(); ++i)
    points->SetPoint(i, g.points_mm(i, 0), g.points_mm(i, 1), g.points_mm(i, 2));
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->Allocate(g.tets.rows());
  for (Eigen::Index t = 0; t < g.tets.rows(); ++t) {
    const vtkIdType ids[4] = {g.tets(t, 0), g.tets(t, 1), g.tets(t, 2), g.tets(t, 3)};
    grid->InsertNextCell(VTK_TETRA, 4, ids);
  }
  vtkNew<vtkDoubleArray> velocity;
  velocity->SetName("velocity_mm_s");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(g.points_mm.rows());
  for (std::size_t k = 0; k < u.values.size(); ++k)
    velocity->SetValue(static_cast<vtkIdType>(k), u.values[k]);
  grid->GetPointData()->AddArray(velocity);
  return grid;
}

double speed_m_s(vtkDataArray* u_mm_s, vtkIdType i) {
  double u[3];
  u_mm_s->GetTuple(i, u);
  return 1e-3 * std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
}

}  // namespace

UrineSection urine_section(const fs::path& vtu) {
  const io::VtuGrid g = io::read_vtu(vtu);
  if (g.tets.rows() == 0) fail(vtu.string(), "has no tetrahedra");
  const io::VtuArray* u = g.point_array("velocity_mm_s");
  if (!u || u->components != 3 ||
      u->values.size() != 3 * static_cast<std::size_t>(g.points_mm.rows()))
    fail(vtu.string(), "has no velocity_mm_s on every node");
  UrineSection s;
  set_plane(s, g, vtu);
  for (std::size_t i = 0; i < u->values.size(); i += 3)
    s.max_speed_m_s = std::max(s.max_speed_m_s, 1e-3 * std::hypot(u->values[i], u->values[i + 1],
                                                                  u->values[i + 2]));
  if (!std::isfinite(s.max_speed_m_s)) fail(vtu.string(), "velocity_mm_s is not finite");
  const vtkSmartPointer<vtkUnstructuredGrid> grid = tet_grid(g, *u);

  vtkNew<vtkPlane> plane;
  plane->SetOrigin(s.origin.data());
  plane->SetNormal(s.normal.data());
  vtkNew<vtkCutter> cutter;
  cutter->SetInputData(grid);
  cutter->SetCutFunction(plane);
  cutter->GenerateTrianglesOff();  // the tets' own sections (triangles and quads)
  cutter->Update();
  vtkPolyData* cut = cutter->GetOutput();
  vtkDataArray* cu = cut->GetPointData()->GetArray("velocity_mm_s");
  if (!cu || cut->GetNumberOfCells() == 0)
    fail(vtu.string(), "the plane through the outlet axis cuts no tetrahedron");
  for (vtkIdType i = 0; i < cut->GetNumberOfPoints(); ++i) {
    double x[3];
    cut->GetPoint(i, x);
    s.points_mm.emplace_back(x[0], x[1], x[2]);
    s.speed_m_s.push_back(speed_m_s(cu, i));
  }
  for (vtkIdType c = 0; c < cut->GetNumberOfCells(); ++c) {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    cut->GetCellPoints(c, n, ids);
    if (n < 3) continue;
    s.polygons.emplace_back(ids, ids + n);
  }
  return s;
}

}  // namespace vesica::compare
