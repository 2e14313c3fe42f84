#pragma once
// Closed surfaces passed between stages, format by extension, coordinates in mm:
//  .vtp  VTK XML polydata: double points, Int32 cell array "region", field data "units"=mm
//  .stl  binary (float32, as the format stores) or ASCII
//  .ply  binary little-endian PLY (float32)
//  .obj  Wavefront OBJ
// STL/PLY/OBJ carry their tags in the sidecar "<file>.regions.json" (RegionsSidecar.h).
// Every stage reads through read_surface_file, so one file means one thing everywhere:
//  - polygons are triangulated, lines and vertices ignored, identical points joined (a
//    surface saved as separate triangles shares its nodes again); points are numbered in
//    the order the triangles first use them;
//  - tags: the VTP's "region" array or the sidecar's, one per triangle in file order; when
//    the triangle count no longer matches the sidecar's (the surface was edited), each
//    triangle takes the tag of the nearest recorded triangle centroid and a note says so
//    with both counts; without any tags `region` is empty and a note says so: the caller
//    applies its automatic outlet and warns, it never silently meshes a wall without one.
// All files are read with VTK's readers (assimp's PLY importer crashes on malformed files),
// after a check that the header's counts fit the file's size.
#include <filesystem>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "vesica/io/TaggedSurface.h"

class vtkPolyData;

namespace vesica::io {

struct SurfaceFile {
  TaggedSurface surface;
  std::vector<std::string> notes;  // re-tagged after an edit, or no tags (also logged)
};

// Throws vesica::Error naming the file when it is missing, unreadable, not in mm, has no
// triangles, has an unknown region code, or a sidecar that cannot be applied.
SurfaceFile read_surface_file(const std::filesystem::path& path);

struct SurfaceWriteOptions {
  bool stl_ascii = false;  // ASCII instead of binary STL
};

// Writes atomically, and the sidecar for formats without cell data.
void write_surface_file(const TaggedSurface& surface, const std::filesystem::path& path,
                        const SurfaceWriteOptions& options = {});

bool is_surface_file(const std::filesystem::path& path);  // by extension

// Polygons already in memory, converted as read_surface_file does (tags from the cell
// array "region" when present); `origin` names them in errors.
TaggedSurface surface_from_polydata(vtkPolyData* polydata, const std::string& origin);

// The polydata written for a surface: double points, Int32 "region" (wall when untagged),
// field data units = mm.
vtkSmartPointer<vtkPolyData> surface_polydata(const TaggedSurface& surface);

}  // namespace vesica::io
