#pragma once
// The pieces of VTK's XML formats that both ParaView series writers (the wall's
// VtuSeriesWriter and the urine's FluidVtuSeries) need: an ASCII DataArray, the mesh part
// of a .vtu in millimetres, and the .pvd collection that lists the steps with their times.
#include <array>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "vesica/core/Units.h"

namespace vesica::simulate {

// <DataArray> of `count` tuples of `components` values; value(i, c) gives each one.
template <class F>
void vtk_data_array(std::ostringstream& s, const char* type, const char* name, int components,
                    std::size_t count, const F& value) {
  s << "<DataArray type=\"" << type << "\" Name=\"" << name << "\" NumberOfComponents=\""
    << components << "\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < count; ++i) {
    for (int c = 0; c < components; ++c) s << value(i, c) << ' ';
    s << '\n';
  }
  s << "</DataArray>\n";
}

// Opens a .vtu (field data units = mm) and writes its points, x_m in metres written in mm,
// and its cells of N nodes of VTK type vtk_type. The caller adds PointData/CellData, then
// vtu_end().
template <std::size_t N>
void vtu_mesh_mm(std::ostringstream& s, const std::vector<Eigen::Vector3d>& x_m,
                 const std::vector<std::array<int, N>>& cells, int vtk_type) {
  const std::size_t nn = x_m.size(), ne = cells.size();
  // "mm" as the ASCII codes of a VTK string array.
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
       "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<FieldData>\n"
       "<Array type=\"String\" Name=\"units\" NumberOfTuples=\"1\" format=\"ascii\">109 109 0"
       "</Array>\n</FieldData>\n";
  s << "<Piece NumberOfPoints=\"" << nn << "\" NumberOfCells=\"" << ne << "\">\n<Points>\n";
  vtk_data_array(s, "Float64", "Points", 3, nn,
                 [&](std::size_t i, int c) { return units::mm_from_m(x_m[i](c)); });
  s << "</Points>\n<Cells>\n";
  // One component: VTK's XML reader rejects a multi-component connectivity array.
  vtk_data_array(s, "Int64", "connectivity", 1, N * ne,
                 [&](std::size_t k, int) { return cells[k / N][k % N]; });
  vtk_data_array(s, "Int64", "offsets", 1, ne, [&](std::size_t e, int) { return N * (e + 1); });
  vtk_data_array(s, "UInt8", "types", 1, ne, [&](std::size_t, int) { return vtk_type; });
  s << "</Cells>\n";
}

inline void vtu_end(std::ostringstream& s) {
  s << "</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

// A .pvd collection of (time in s, file relative to the .pvd) steps.
inline std::string pvd_text(const std::vector<std::pair<double, std::string>>& steps) {
  std::ostringstream s;
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n";
  for (const auto& [t, file] : steps)
    s << "<DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
  s << "</Collection>\n</VTKFile>\n";
  return s.str();
}

}  // namespace vesica::simulate
