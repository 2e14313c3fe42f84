#include "vesica/io/SurfaceFile.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOBJWriter.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "LowerCase.h"
#include "PlyCheck.h"
#include "SurfaceHeaderCheck.h"
#include "VtkErrors.h"
#include "VtkXmlCheck.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/core/SideOutputNames.h"
#include "vesica/io/BladderScale.h"
#include "vesica/io/RegionsSidecar.h"

namespace vesica::io {
namespace {

std::string lower_extension(const std::filesystem::path& path) {
  return detail::lower_case(path.extension().string());
}

// The file's polygons as VTK reads them, before any cleaning (so that a sidecar's tags,
// one per triangle in file order, still line up with the cells).
vtkSmartPointer<vtkPolyData> read_polydata(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  const std::string name = path.string();
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".vtp") {
    detail::check_vtk_xml_counts(path);
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    if (!xml->CanReadFile(name.c_str())) fail(name, "not a readable VTK XML polydata file");
    xml->SetFileName(name.c_str());
    reader = xml;
  } else if (ext == ".stl") {
    detail::check_stl_size(path);
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->MergingOff();  // keep every triangle (and its sidecar tag); points are joined below
    stl->SetFileName(name.c_str());
    reader = stl;
  } else if (ext == ".ply") {
    detail::check_ply_file(path);
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(name.c_str());
    reader = ply;
  } else {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(name.c_str());
    reader = obj;
  }
  const auto errors = detail::watch_errors(reader);
  detail::update_reader(*reader, name);
  if (errors->any())
    fail(name, "cannot read the surface: " + detail::vtk_message_line(errors->message()));
  return vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
}

void require_millimetres(vtkPolyData* polydata, const std::string& origin) {
  auto* units = vtkStringArray::SafeDownCast(polydata->GetFieldData()->GetAbstractArray("units"));
  if (units && units->GetNumberOfValues() > 0 && units->GetValue(0) != "mm")
    fail(origin, "coordinates are in '" + units->GetValue(0) + "', expected mm");
}

// Every polygon's corners name existing points, and the points are finite: VTK's filters
// index points by the ids a reader took from the file, without checking them.
void require_valid_polygons(vtkPolyData* polydata, const std::string& origin) {
  const vtkIdType points = polydata->GetNumberOfPoints();
  for (vtkIdType i = 0; i < points; ++i) {
    double p[3];
    polydata->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(origin, "point " + std::to_string(i) + " has a coordinate that is not finite");
  }
  vtkCellArray* polys = polydata->GetPolys();
  vtkNew<vtkIdList> ids;
  polys->InitTraversal();
  for (vtkIdType c = 0; polys->GetNextCell(ids); ++c) {
    if (ids->GetNumberOfIds() < 3)
      fail(origin, "polygon " + std::to_string(c) + " has fewer than 3 corners");
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      if (ids->GetId(k) < 0 || ids->GetId(k) >= points)
        fail(origin, "polygon " + std::to_string(c) + " names point " +
                         std::to_string(ids->GetId(k)) + " of " + std::to_string(points));
  }
}

int region_code(double value, const std::string& origin) {
  const int code = static_cast<int>(value);
  for (Region r : kAllRegions)
    if (static_cast<int>(r) == code && code == value) return code;
  fail(origin, "unknown region code " + std::to_string(value) + " in cell array 'region'",
       "codes are wall=1, outlet=2, inlet=3, fixed=4, support=5");
}

void attach_tags(const Eigen::VectorXi& tags, vtkPolyData* polydata) {
  vtkNew<vtkIntArray> region;
  region->SetName("region");
  region->SetNumberOfValues(tags.size());
  for (Eigen::Index i = 0; i < tags.size(); ++i) region->SetValue(i, tags(i));
  polydata->GetCellData()->AddArray(region);
}

// Sidecar tags for a file without cell data: attached to the cells when one per triangle
// (they then follow the cleaning), else returned for the nearest-centroid rule.
std::optional<RegionsSidecar> apply_sidecar(const std::filesystem::path& path,
                                            vtkPolyData* polydata) {
  const std::filesystem::path sidecar_path = regions_sidecar_path(path);
  std::optional<RegionsSidecar> sidecar = read_regions_sidecar(sidecar_path);
  if (!sidecar) return std::nullopt;
  const bool one_per_triangle = sidecar->region.size() == polydata->GetNumberOfPolys() &&
                                polydata->GetNumberOfCells() == polydata->GetNumberOfPolys();
  if (one_per_triangle) {
    attach_tags(sidecar->region, polydata);
    return std::nullopt;
  }
  if (sidecar->centroids.rows() == 0)
    fail(sidecar_path.string(),
         std::to_string(sidecar->region.size()) + " region tags for " +
             std::to_string(polydata->GetNumberOfPolys()) +
             " triangles and no recorded centroids to re-tag the edited surface from",
         "rerun vesica-surface on the surface, or delete the sidecar to use the automatic outlet");
  return sidecar;
}

std::string retag_note(const std::filesystem::path& path, const RegionsSidecar& sidecar,
                       Eigen::Index triangles) {
  return path.string() + ": " + std::to_string(sidecar.region.size()) + " region tags for " +
         std::to_string(triangles) +
         " triangles (surface edited); each triangle takes the tag of the nearest recorded "
         "triangle centroid";
}

// Errors name `target`, the file the user asked for, not the temporary written.
template <class Writer>
void run_writer(Writer* writer, vtkPolyData* poly, const std::filesystem::path& tmp,
                const std::filesystem::path& target) {
  writer->SetInputData(poly);
  writer->SetFileName(tmp.c_str());
  const auto errors = detail::watch_errors(writer);
  if (!writer->Write() || errors->any() || writer->GetErrorCode() != vtkErrorCode::NoError)
    fail(target.string(), "VTK could not write the surface: " +
                              detail::vtk_write_error(*errors, writer->GetErrorCode()));
}

void write_polydata(vtkPolyData* poly, const std::string& ext, const SurfaceWriteOptions& options,
                    const std::filesystem::path& tmp, const std::filesystem::path& target) {
  if (ext == ".vtp") {
    vtkNew<vtkXMLPolyDataWriter> writer;
    // Appended, not inline: VTK 9.1's inline binary mode frees unallocated memory when the
    // disk fills during the write.
    writer->SetDataModeToAppended();
    run_writer(writer.Get(), poly, tmp, target);
  } else if (ext == ".stl") {
    vtkNew<vtkSTLWriter> writer;
    if (options.stl_ascii)
      writer->SetFileTypeToASCII();
    else
      writer->SetFileTypeToBinary();
    run_writer(writer.Get(), poly, tmp, target);
  } else if (ext == ".ply") {
    vtkNew<vtkPLYWriter> writer;
    writer->SetFileTypeToBinary();
    run_writer(writer.Get(), poly, tmp, target);
  } else {
    vtkNew<vtkOBJWriter> writer;
    run_writer(writer.Get(), poly, tmp, target);
  }
}

}  // namespace

bool is_surface_file(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  return ext == ".vtp" || ext == ".stl" || ext == ".ply" || ext == ".obj";
}

TaggedSurface surface_from_polydata(vtkPolyData* input, const std::string& origin) {
  if (!input || input->GetNumberOfPolys() == 0) fail(origin, "no surface polygons");
  require_millimetres(input, origin);
  require_valid_polygons(input, origin);
  // Vertices, lines and strips are not wall; keep only polygons, then triangulate.
  vtkNew<vtkPolyData> polys;
  polys->SetPoints(input->GetPoints());
  polys->SetPolys(input->GetPolys());
  const vtkIdType first_poly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  if (vtkDataArray* region = input->GetCellData()->GetArray("region")) {
    vtkNew<vtkIntArray> poly_region;  // the polygons' tags: cells after verts and lines
    poly_region->SetName("region");
    poly_region->SetNumberOfValues(input->GetNumberOfPolys());
    for (vtkIdType c = 0; c < input->GetNumberOfPolys(); ++c)
      poly_region->SetValue(c, region_code(region->GetTuple1(first_poly + c), origin));
    polys->GetCellData()->AddArray(poly_region);
  }
  vtkNew<vtkTriangleFilter> triangulate;
  triangulate->SetInputData(polys);
  triangulate->PassVertsOff();
  triangulate->PassLinesOff();
  vtkNew<vtkCleanPolyData> clean;  // joins identical points, drops unused ones
  clean->SetInputConnection(triangulate->GetOutputPort());
  clean->PointMergingOn();
  clean->SetTolerance(0.0);
  clean->ConvertPolysToLinesOff();
  clean->ConvertLinesToPointsOff();
  clean->Update();
  vtkPolyData* out = clean->GetOutput();

  TaggedSurface s;
  s.points_mm.resize(out->GetNumberOfPoints(), 3);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail(origin, "point " + std::to_string(i) + " has a coordinate that is not finite");
    s.points_mm.row(i) << p[0], p[1], p[2];
  }
  vtkDataArray* region = out->GetCellData()->GetArray("region");
  vtkCellArray* cells = out->GetPolys();
  s.triangles.resize(cells->GetNumberOfCells(), 3);
  if (region) s.region.resize(cells->GetNumberOfCells());
  vtkNew<vtkIdList> ids;
  cells->InitTraversal();
  for (vtkIdType c = 0; cells->GetNextCell(ids); ++c) {
    if (ids->GetNumberOfIds() != 3) fail(origin, "a polygon could not be triangulated");
    for (int k = 0; k < 3; ++k) s.triangles(c, k) = static_cast<int>(ids->GetId(k));
    if (region) s.region(c) = static_cast<int>(region->GetTuple1(c));
  }
  if (s.triangles.rows() == 0) fail(origin, "no triangles left after cleaning");
  return s;
}

SurfaceFile read_surface_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (!std::filesystem::exists(path)) fail(name, "surface file not found");
  if (!is_surface_file(path)) fail(name, "unknown surface format", "use .vtp, .stl, .ply or .obj");
  require_input_file(path, kMaxMeshFileBytes, "surface");
  vtkSmartPointer<vtkPolyData> polydata = read_polydata(path);
  if (!polydata || polydata->GetNumberOfPolys() == 0) fail(name, "the surface has no triangles");
  const std::optional<RegionsSidecar> edited =
      lower_extension(path) == ".vtp" ? std::nullopt : apply_sidecar(path, polydata);
  SurfaceFile file;
  file.surface = surface_from_polydata(polydata, name);
  const Eigen::MatrixXd& p = file.surface.points_mm;
  check_surface_span((p.colwise().maxCoeff() - p.colwise().minCoeff()).maxCoeff(), name);
  if (edited) {
    file.surface.region =
        retag_by_nearest_centroid(edited->centroids, edited->region, file.surface);
    file.notes.push_back(retag_note(path, *edited, file.surface.triangles.rows()));
  } else if (!file.surface.has_regions()) {
    file.notes.push_back(name + ": no region tags (no \"region\" cell array" +
                         (lower_extension(path) == ".vtp"
                              ? std::string(")")
                              : " and no " + regions_sidecar_path(path).filename().string() + ")"));
  }
  for (const std::string& note : file.notes) log()->warn("{}", note);
  return file;
}

vtkSmartPointer<vtkPolyData> surface_polydata(const TaggedSurface& surface) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(surface.points_mm.rows());
  for (Eigen::Index i = 0; i < surface.points_mm.rows(); ++i)
    points->SetPoint(i, surface.points_mm(i, 0), surface.points_mm(i, 1), surface.points_mm(i, 2));
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index f = 0; f < surface.triangles.rows(); ++f) {
    const vtkIdType ids[3] = {surface.triangles(f, 0), surface.triangles(f, 1),
                              surface.triangles(f, 2)};
    polys->InsertNextCell(3, ids);
  }
  auto polydata = vtkSmartPointer<vtkPolyData>::New();
  polydata->SetPoints(points);
  polydata->SetPolys(polys);
  attach_tags(surface.has_regions() ? surface.region
                                    : Eigen::VectorXi::Constant(surface.triangles.rows(),
                                                                static_cast<int>(Region::Wall)),
              polydata);
  vtkNew<vtkStringArray> units;
  units->SetName("units");
  units->InsertNextValue("mm");
  polydata->GetFieldData()->AddArray(units);
  return polydata;
}

void write_surface_file(const TaggedSurface& surface, const std::filesystem::path& path,
                        const SurfaceWriteOptions& options) {
  const std::string ext = lower_extension(path);
  if (!is_surface_file(path))
    fail(path.string(), "unknown surface format", "use .vtp, .stl, .ply or .obj");
  const vtkSmartPointer<vtkPolyData> poly = surface_polydata(surface);
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    write_polydata(poly, ext, options, tmp, path);
  });
  if (surface_needs_sidecar(path.string()))
    write_regions_sidecar(surface, regions_sidecar_path(path));
}

}  // namespace vesica::io
