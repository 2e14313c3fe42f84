#include "vesica/mesh/SurfaceReader.h"

#include <vtkAbstractPolyDataReader.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cctype>
#include <fstream>

#include <nlohmann/json.hpp>

#include "vesica/core/Error.h"
#include "vesica/core/Regions.h"

namespace vesica::mesh {

namespace {

std::string lower_extension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

vtkSmartPointer<vtkPolyData> read_polydata(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  const std::string name = path.string();
  if (ext == ".vtp") {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(name.c_str());
    if (!reader->CanReadFile(name.c_str())) fail(name, "not a readable VTK XML PolyData file");
    reader->Update();
    return reader->GetOutput();
  }
  vtkSmartPointer<vtkAbstractPolyDataReader> reader;
  if (ext == ".stl") reader = vtkSmartPointer<vtkSTLReader>::New();
  if (ext == ".ply") reader = vtkSmartPointer<vtkPLYReader>::New();
  if (ext == ".obj") reader = vtkSmartPointer<vtkOBJReader>::New();
  if (!reader) fail(name, "unknown surface format '" + ext + "'", "use .vtp, .stl, .ply or .obj");
  reader->SetFileName(name.c_str());
  reader->Update();
  return reader->GetOutput();
}

void require_millimetres(vtkPolyData* polydata, const std::string& origin) {
  auto* units = vtkStringArray::SafeDownCast(polydata->GetFieldData()->GetAbstractArray("units"));
  if (units && units->GetNumberOfValues() > 0 && units->GetValue(0) != "mm")
    fail(origin, "coordinates are in '" + units->GetValue(0) + "', expected mm");
}

int region_code(double value, const std::string& origin) {
  const int code = static_cast<int>(value);
  for (Region r : kAllRegions)
    if (static_cast<int>(r) == code && code == value) return code;
  fail(origin, "unknown region code " + std::to_string(value) + " in cell array 'region'",
       "codes are wall=1, outlet=2, inlet=3, fixed=4, support=5");
}

// STL/PLY/OBJ carry no cell data; vesica-surface writes their tags beside them in
// "<file>.regions.json" ({"region": [one code per triangle, in file order]}).
void attach_sidecar_regions(vtkPolyData* polydata, const std::filesystem::path& path) {
  const std::filesystem::path sidecar = path.string() + ".regions.json";
  if (!std::filesystem::exists(sidecar)) return;
  nlohmann::json j;
  try {
    std::ifstream in(sidecar);
    j = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    fail(sidecar.string(), std::string("not valid JSON: ") + e.what());
  }
  if (!j.contains("region") || !j["region"].is_array()) fail(sidecar.string(), "no array 'region'");
  const auto& tags = j["region"];
  if (static_cast<vtkIdType>(tags.size()) != polydata->GetNumberOfPolys() ||
      polydata->GetNumberOfCells() != polydata->GetNumberOfPolys())
    fail(sidecar.string(),
         std::to_string(tags.size()) + " region tags for " +
             std::to_string(polydata->GetNumberOfPolys()) + " triangles",
         "was the surface edited after vesica-surface wrote it?");
  vtkNew<vtkIntArray> region;
  region->SetName("region");
  for (const auto& tag : tags) region->InsertNextValue(tag.get<int>());
  polydata->GetCellData()->AddArray(region);
}

}  // namespace

SurfaceMesh surface_from_polydata(vtkPolyData* input, const std::string& origin) {
  if (!input || input->GetNumberOfPolys() == 0) fail(origin, "no surface polygons");
  require_millimetres(input, origin);
  // Vertices, lines and strips are not wall; keep only polygons, then triangulate.
  vtkNew<vtkPolyData> polys;
  polys->SetPoints(input->GetPoints());
  polys->SetPolys(input->GetPolys());
  polys->GetCellData()->ShallowCopy(input->GetCellData());
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(polys);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  vtkNew<vtkCleanPolyData> clean;  // joins duplicate points, drops unused ones
  clean->SetInputConnection(triangulate->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->Update();
  vtkPolyData* out = clean->GetOutput();

  SurfaceMesh s;
  s.points.resize(out->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    s.points.row(i) << p[0], p[1], p[2];
  }
  vtkDataArray* region = out->GetCellData()->GetArray("region");
  vtkCellArray* cells = out->GetPolys();
  s.triangles.resize(cells->GetNumberOfCells(), 3);
  s.region.resize(cells->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  // Polys are the first cells of the output (no verts/lines were passed).
  cells->InitTraversal();
  for (vtkIdType c = 0; cells->GetNextCell(ids); ++c) {
    if (ids->GetNumberOfIds() != 3) fail(origin, "a polygon could not be triangulated");
    for (int k = 0; k < 3; ++k) s.triangles(c, k) = static_cast<int>(ids->GetId(k));
    s.region(c) =
        region ? region_code(region->GetComponent(c, 0), origin) : static_cast<int>(Region::Wall);
  }
  if (s.triangles.rows() == 0) fail(origin, "no triangles left after cleaning");
  return s;
}

SurfaceMesh read_surface(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) fail(path.string(), "file not found");
  vtkSmartPointer<vtkPolyData> polydata = read_polydata(path);
  if (lower_extension(path) != ".vtp") attach_sidecar_regions(polydata, path);
  return surface_from_polydata(polydata, path.string());
}

}  // namespace vesica::mesh
