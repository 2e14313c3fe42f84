#pragma once
// Reading the bladder surface: .vtp (with the cell array "region" and field data
// "units"), .stl, .ply, .obj. Duplicate points are joined and polygons triangulated, so
// that a surface exported as separate triangles still shares its nodes.
#include <filesystem>
#include <string>

#include "vesica/mesh/SurfaceMesh.h"

class vtkPolyData;

namespace vesica::mesh {

// Throws vesica::Error naming `path` when the file is missing, unreadable, not in mm,
// has no triangles or carries unknown region codes. Triangles without a region are wall.
SurfaceMesh read_surface(const std::filesystem::path& path);

// The same conversion from polygons already in memory; `origin` names them in errors.
SurfaceMesh surface_from_polydata(vtkPolyData* polydata, const std::string& origin);

}  // namespace vesica::mesh
