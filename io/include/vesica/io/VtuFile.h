#pragma once
// VTK XML unstructured grids (.vtu) of triangles and tetrahedra, in mm (field data
// "length_unit_m" = 0.001), written and read with VTK's own writer and reader, and readable
// by meshio (no String arrays: its reader stops at them).
//  - VtuGrid: any such grid with named point and cell arrays (the ParaView series,
//    PvdSeries.h, and the mesh below);
//  - the mesh file of vesica-mesh (beside its .msh): triangles then tetrahedra; cell data
//    "region" (Int32, tetrahedra 10), "thickness_mm" (Float64, tetrahedra 0), "fiber1",
//    "fiber2" (3-vectors, tetrahedra 0).
// Field data (one tuple for the whole grid) holds numbers only, such as a series step's
// "time_s", "volume_ml" and "pdet_cmh2o", besides the unit (read_vtu checks it and leaves it
// out of field_data; it also accepts the "units" = "mm" string of older files).
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "vesica/io/VolumeMesh.h"

namespace vesica::io {

struct VtuArray {
  std::string name;  // with its unit: "displacement_mm", "pressure_cmh2o"
  int components = 1;
  std::vector<double> values;  // tuple-major: components values per point or cell
  bool integer = false;        // written as Int32 (tags)
};

struct VtuGrid {
  Eigen::MatrixXd points_mm;         // N x 3
  Eigen::MatrixXi triangles;         // M x 3
  Eigen::MatrixXi tets;              // K x 4
  std::vector<VtuArray> point_data;  // N tuples each
  std::vector<VtuArray> cell_data;   // M + K tuples each: triangles first, then tetrahedra
  std::vector<VtuArray> field_data;  // one tuple each (numbers only)

  const VtuArray* cell_array(const std::string& name) const;
  const VtuArray* point_array(const std::string& name) const;
  const VtuArray* field_array(const std::string& name) const;
};

struct VtuWriteOptions {
  bool compress = true;  // zlib; off for the many frames of a series (speed)
};

// Writes atomically; throws vesica::Error naming the file when VTK cannot write it or an
// array's length does not match the points or cells.
void write_vtu(const VtuGrid& grid, const std::filesystem::path& path,
               const VtuWriteOptions& options = {});

// Reads any VTK XML unstructured grid of triangles and tetrahedra (cell arrays reordered
// with the cells: triangles first). Throws vesica::Error naming the file when it is not
// one, is not in mm, or holds another cell type or a non-finite point.
VtuGrid read_vtu(const std::filesystem::path& path);

// The mesh file of vesica-mesh.
void write_mesh_vtu(const VolumeMesh& mesh, const std::filesystem::path& path);
// Missing arrays: region wall, thickness and fibers empty.
VolumeMesh read_mesh_vtu(const std::filesystem::path& path);

// "<dir>/<stem>.vtu" beside a .msh path.
std::filesystem::path vtu_beside(const std::filesystem::path& msh_path);

}  // namespace vesica::io
