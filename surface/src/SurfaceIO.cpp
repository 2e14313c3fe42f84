#include "vesica/surface/SurfaceIO.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <vtkFieldData.h>
#include <vtkOBJWriter.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkSTLWriter.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <assimp/Importer.hpp>
#include <nlohmann/json.hpp>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/core/Log.h"
#include "vesica/core/Regions.h"
#include "vesica/surface/Topology.h"
#include "vesica/surface/VtkConversion.h"

namespace vesica::surface {

namespace {

std::string extension_of(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

TriangleSurface read_vtp(const std::filesystem::path& path) {
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  if (!reader->CanReadFile(path.c_str())) fail(path.string(), "not a readable VTK XML polydata");
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  if (auto* units = vtkStringArray::SafeDownCast(poly->GetFieldData()->GetAbstractArray("units")))
    if (units->GetNumberOfValues() > 0 && units->GetValue(0) != "mm")
      fail(path.string(), "units are \"" + units->GetValue(0) + "\", expected \"mm\"");
  return from_polydata(poly);
}

TriangleSurface read_with_assimp(const std::filesystem::path& path) {
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path.string(), aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                           aiProcess_DropNormals | aiProcess_PreTransformVertices);
  if (!scene)
    fail(path.string(), std::string("cannot read the surface: ") + importer.GetErrorString());
  TriangleSurface out;
  std::vector<Eigen::RowVector3d> points;
  std::vector<Eigen::RowVector3i> triangles;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh* mesh = scene->mMeshes[m];
    const int offset = static_cast<int>(points.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      points.emplace_back(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z);
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
      if (mesh->mFaces[f].mNumIndices == 3)
        triangles.emplace_back(offset + static_cast<int>(mesh->mFaces[f].mIndices[0]),
                               offset + static_cast<int>(mesh->mFaces[f].mIndices[1]),
                               offset + static_cast<int>(mesh->mFaces[f].mIndices[2]));
  }
  out.V.resize(points.size(), 3);
  for (std::size_t i = 0; i < points.size(); ++i) out.V.row(i) = points[i];
  out.F.resize(triangles.size(), 3);
  for (std::size_t i = 0; i < triangles.size(); ++i) out.F.row(i) = triangles[i];
  // Across meshes (and for readers that keep per-face vertices) equal points still repeat.
  merge_identical_vertices(out.V, out.F);
  return out;
}

Eigen::MatrixXd triangle_centroids(const TriangleSurface& s) {
  Eigen::MatrixXd c(s.F.rows(), 3);
  for (Eigen::Index f = 0; f < s.F.rows(); ++f)
    c.row(f) = (s.V.row(s.F(f, 0)) + s.V.row(s.F(f, 1)) + s.V.row(s.F(f, 2))) / 3.0;
  return c;
}

// A surface edited elsewhere (triangles added, removed, remeshed) no longer matches its
// tags one to one: each triangle takes the tag of the nearest triangle centroid recorded.
bool transfer_tags_by_centroid(const nlohmann::json& j, TriangleSurface& surface) {
  if (!j.contains("centroids_mm")) return false;
  const auto& flat = j.at("centroids_mm");
  const auto& tags = j.at("region");
  const Eigen::Index n = static_cast<Eigen::Index>(tags.size());
  if (static_cast<Eigen::Index>(flat.size()) != 3 * n || n * surface.F.rows() > 200'000'000)
    return false;
  Eigen::MatrixXd recorded(n, 3);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int d = 0; d < 3; ++d) recorded(i, d) = flat[3 * i + d].get<double>();
  const Eigen::MatrixXd centroids = triangle_centroids(surface);
  surface.region.resize(surface.F.rows());
  for (Eigen::Index f = 0; f < surface.F.rows(); ++f) {
    Eigen::Index nearest = 0;
    (recorded.rowwise() - centroids.row(f)).rowwise().squaredNorm().minCoeff(&nearest);
    surface.region(f) = tags[nearest].get<int>();
  }
  return true;
}

void read_sidecar(const std::filesystem::path& path, TriangleSurface& surface) {
  const auto sidecar = regions_sidecar_path(path);
  if (!std::filesystem::exists(sidecar)) return;
  nlohmann::json j;
  try {
    std::ifstream in(sidecar);
    j = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    fail(sidecar.string(), std::string("not valid JSON: ") + e.what());
  }
  if (!j.contains("region") || !j.at("region").is_array())
    fail(sidecar.string(), "no \"region\" array of tags");
  const auto& tags = j.at("region");
  if (static_cast<Eigen::Index>(tags.size()) == surface.F.rows()) {
    surface.region.resize(surface.F.rows());
    for (Eigen::Index f = 0; f < surface.F.rows(); ++f) surface.region(f) = tags[f].get<int>();
  } else if (transfer_tags_by_centroid(j, surface)) {
    log()->warn(
        "{}: {} tags for {} triangles (surface edited); tags taken from the nearest "
        "recorded triangle",
        sidecar.string(), tags.size(), surface.F.rows());
  } else {
    log()->warn("{}: {} region tags for {} triangles; tags ignored", sidecar.string(), tags.size(),
                surface.F.rows());
  }
}

nlohmann::json sidecar_json(const TriangleSurface& surface) {
  nlohmann::json names = nlohmann::json::object();
  for (Region r : kAllRegions) names[std::to_string(static_cast<int>(r))] = region_name(r);
  const Eigen::VectorXi tags = surface.regions_or_wall();
  // Row-major x,y,z per triangle, so tags can follow triangles through outside edits.
  const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> centroids =
      triangle_centroids(surface);
  return {
      {"units", "mm"},
      {"triangle_count", surface.F.rows()},
      {"region_names", names},
      {"region", std::vector<int>(tags.data(), tags.data() + tags.size())},
      {"centroids_mm", std::vector<double>(centroids.data(), centroids.data() + centroids.size())}};
}

void write_polydata(vtkPolyData* poly, const std::string& ext, const WriteOptions& options,
                    const std::filesystem::path& tmp) {
  if (ext == ".vtp") {
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetInputData(poly);
    writer->SetFileName(tmp.c_str());
    writer->SetDataModeToBinary();
    if (!writer->Write()) fail(tmp.string(), "VTK could not write the file");
  } else if (ext == ".stl") {
    auto writer = vtkSmartPointer<vtkSTLWriter>::New();
    writer->SetInputData(poly);
    writer->SetFileName(tmp.c_str());
    if (options.stl_ascii)
      writer->SetFileTypeToASCII();
    else
      writer->SetFileTypeToBinary();
    if (!writer->Write()) fail(tmp.string(), "VTK could not write the file");
  } else if (ext == ".ply") {
    auto writer = vtkSmartPointer<vtkPLYWriter>::New();
    writer->SetInputData(poly);
    writer->SetFileName(tmp.c_str());
    writer->SetFileTypeToBinary();
    if (!writer->Write()) fail(tmp.string(), "VTK could not write the file");
  } else {
    auto writer = vtkSmartPointer<vtkOBJWriter>::New();
    writer->SetInputData(poly);
    writer->SetFileName(tmp.c_str());
    if (!writer->Write()) fail(tmp.string(), "VTK could not write the file");
  }
}

}  // namespace

std::filesystem::path regions_sidecar_path(const std::filesystem::path& surface_path) {
  return surface_path.string() + ".regions.json";
}

bool is_surface_file(const std::filesystem::path& path) {
  const std::string ext = extension_of(path);
  return ext == ".vtp" || ext == ".stl" || ext == ".ply" || ext == ".obj";
}

TriangleSurface read_surface(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) fail(path.string(), "surface file not found");
  if (!is_surface_file(path))
    fail(path.string(), "unknown surface format", "use .vtp, .stl, .ply or .obj");
  TriangleSurface surface;
  if (extension_of(path) == ".vtp") {
    surface = read_vtp(path);
  } else {
    surface = read_with_assimp(path);
    read_sidecar(path, surface);
  }
  if (surface.F.rows() == 0) fail(path.string(), "the surface has no triangles");
  return surface;
}

void write_surface(const TriangleSurface& surface, const std::filesystem::path& path,
                   const WriteOptions& options) {
  const std::string ext = extension_of(path);
  if (!is_surface_file(path))
    fail(path.string(), "unknown surface format", "use .vtp, .stl, .ply or .obj");
  auto poly = to_polydata(surface);
  write_atomically(
      path, [&](const std::filesystem::path& tmp) { write_polydata(poly, ext, options, tmp); });
  if (ext != ".vtp")
    write_text_atomically(regions_sidecar_path(path), sidecar_json(surface).dump(1) + "\n");
}

}  // namespace vesica::surface
