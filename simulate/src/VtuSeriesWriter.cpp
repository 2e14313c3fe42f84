#include "vesica/simulate/VtuSeriesWriter.h"

#include <cstdio>
#include <sstream>

#include "VtkXmlText.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {
namespace {
constexpr int kVtkTriangle = 5;
}  // namespace

std::string wall_vtu_text(const WallModel& wall, const std::vector<Eigen::Vector3d>& x,
                          const std::vector<MembraneStressOutput>& st) {
  std::ostringstream s;
  s.precision(9);
  const std::size_t nn = wall.node_count(), ne = wall.triangle_count();
  vtu_mesh_mm(s, x, wall.triangles, kVtkTriangle);
  s << "<PointData Vectors=\"displacement_mm\">\n";
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
  s << "</CellData>\n";
  vtu_end(s);
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
