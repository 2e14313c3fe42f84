#pragma once
// Reading and writing surfaces, format by extension:
//  .vtp  VTK XML polydata: double points, Int32 cell array "region", field data units=mm
//  .stl  ASCII or binary (float32, as the format stores)
//  .ply  binary PLY, .obj Wavefront OBJ
// STL/PLY/OBJ are read through assimp with identical vertices joined, so a surface edited
// in MeshLab or Blender comes back connected; their region tags travel in a JSON sidecar
// "<file>.regions.json" (one tag per triangle, in file order).
#include <filesystem>

#include "vesica/surface/TriangleSurface.h"

namespace vesica::surface {

struct WriteOptions {
  bool stl_ascii = false;  // ASCII instead of binary STL
};

// Throws vesica::Error naming the file when it cannot be read or holds no triangles.
// Tags come from the VTP cell array or the sidecar; without them `region` stays empty.
TriangleSurface read_surface(const std::filesystem::path& path);

// Writes atomically (and the sidecar for formats without cell data).
void write_surface(const TriangleSurface& surface, const std::filesystem::path& path,
                   const WriteOptions& options = {});

// The sidecar path of a surface file: "<file>.regions.json".
std::filesystem::path regions_sidecar_path(const std::filesystem::path& surface_path);

bool is_surface_file(const std::filesystem::path& path);  // by extension

}  // namespace vesica::surface
