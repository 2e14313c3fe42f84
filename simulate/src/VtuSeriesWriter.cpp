#include "vesica/simulate/VtuSeriesWriter.h"

#include <cstdio>
#include <sstream>

#include "VtkXmlText.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {
std::string wall_vtu_text(const WallModel& wall, const std::vector<Eigen::Vector3d>& x,
                          const std::vector<MembraneStressOutput>& st) {
  std::ostringstream s;
  s.precision(9);
  const std::size_t nn = wall.node_count(), ne = wall.triangle_count();
  s << "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
       "byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n<FieldData>\n"
       "<Array type=\"String\" Name=\"units\" NumberOfTuples=\"1\" format=\"ascii\">109 109 0"
       "</Array>\n</FieldData>\n";
  s << "<Piece NumberOfPoints=\"" << nn << "\" NumberOfCells=\"" << ne << "\">\n<Points>\n";
  vtk_data_array(s, "Float64", "Points", 3, nn,
                 [&](std::size_t i, int c) { return units::mm_from_m(x[i](c)); });
  s << "</Points>\n<Cells>\n";
  // One component: VTK's XML reader rejects a multi-component connectivity array.
  vtk_data_array(s, "Int64", "connectivity", 1, 3 * ne,
                 [&](std::size_t k, int) { return wall.triangles[k / 3][k % 3]; });
  vtk_data_array(s, "Int64", "offsets", 1, ne, [&](std::size_t e, int) { return 3 * (e + 1); });
  vtk_data_array(s, "UInt8", "types", 1, ne, [&](std::size_t, int) { return 5; });
  s << "</Cells>\n<PointData Vectors=\"displacement_mm\">\n";
  vtk_data_array(s, "Float64", "displacement_mm", 3, nn, [&](std::size_t i, int c) {
    return units::mm_from_m(x[i](c) - wall.nodes[i](c));
  });
  s << "</PointData>\n<CellData Scalars=\"region\">\n";
  vtk_data_array(s, "Int32", "region", 1, ne, [&](std::size_t e, int) { return wall.region[e]; });
  vtk_data_array(s, "Float64", "cauchy_principal_kpa", 2, ne, [&](std::size_t e, int c) {
    return units::kpa_from_pa(c == 0 ? st[e].sigma1 : st[e].sigma2);
  });
  vtk_data_array(s, "Float64", "tension_n_per_m", 2, ne, [&](std::size_t e, int c) {
    return (c == 0 ? st[e].sigma1 : st[e].sigma2) * st[e].thickness;
  });
  vtk_data_array(s, "Float64", "thickness_mm", 1, ne,
                 [&](std::size_t e, int) { return units::mm_from_m(st[e].thickness); });
  vtk_data_array(s, "Float64", "stretch", 2, ne,
                 [&](std::size_t e, int c) { return c == 0 ? st[e].stretch1 : st[e].stretch2; });
  s << "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
  return s.str();
}

VtuSeriesWriter::VtuSeriesWriter(std::filesystem::path folder) : folder_(std::move(folder)) {}

void VtuSeriesWriter::add_step(double time_s, const WallModel& wall,
                               const std::vector<Eigen::Vector3d>& x,
                               const std::vector<MembraneStressOutput>& stresses) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%04zu.vtu", steps_.size());
  write_text_atomically(series_folder() / name, wall_vtu_text(wall, x, stresses));
  steps_.emplace_back(time_s, std::string("series/") + name);
}

void VtuSeriesWriter::finish() {
  write_text_atomically(pvd_path(), pvd_text(steps_));
}

}  // namespace vesica::simulate
