#include "vesica/simulate/protocol/VtuSeriesWriter.h"

#include "protocol/SeriesFrames.h"
#include "vesica/core/Units.h"

namespace vesica::simulate {

io::VtuGrid wall_frame(const WallModel& wall, const std::vector<Eigen::Vector3d>& x,
                       const std::vector<MembraneStressOutput>& st) {
  io::VtuGrid g;
  g.points_mm = points_mm(x);
  g.triangles = cell_matrix(wall.triangles);
  const std::size_t nn = wall.node_count(), ne = wall.triangle_count();
  g.point_data.push_back(frame_array("displacement_mm", 3, nn, [&](std::size_t i, int c) {
    return units::mm_from_m(x[i](c) - wall.nodes[i](c));
  }));
  io::VtuArray region =
      frame_array("region", 1, ne, [&](std::size_t e, int) { return wall.region[e]; });
  region.integer = true;
  g.cell_data.push_back(region);
  g.cell_data.push_back(frame_array("cauchy_principal_kpa", 2, ne, [&](std::size_t e, int c) {
    return units::kpa_from_pa(c == 0 ? st[e].sigma1 : st[e].sigma2);
  }));
  g.cell_data.push_back(frame_array("tension_n_per_m", 2, ne, [&](std::size_t e, int c) {
    return (c == 0 ? st[e].sigma1 : st[e].sigma2) * st[e].thickness;
  }));
  g.cell_data.push_back(frame_array("thickness_mm", 1, ne, [&](std::size_t e, int) {
    return units::mm_from_m(st[e].thickness);
  }));
  g.cell_data.push_back(frame_array("stretch", 2, ne, [&](std::size_t e, int c) {
    return c == 0 ? st[e].stretch1 : st[e].stretch2;
  }));
  return g;
}

VtuSeriesWriter::VtuSeriesWriter(std::filesystem::path folder)
    : series_(std::move(folder), "series") {
  series_.set_paraview_script(
      {"cauchy_principal_kpa", 0, "max principal Cauchy stress sigma1 (kPa)", "region", 2});
}

void VtuSeriesWriter::add_step(double time_s, const FrameState& state, const WallModel& wall,
                               const std::vector<Eigen::Vector3d>& x,
                               const std::vector<MembraneStressOutput>& stresses) {
  io::VtuGrid frame = wall_frame(wall, x, stresses);
  frame.field_data = {{"volume_ml", 1, {state.volume_ml}, false},
                      {"pdet_cmh2o", 1, {state.pdet_cmh2o}, false}};
  series_.add_step(time_s, std::move(frame));
}

void VtuSeriesWriter::finish() {
  series_.finish();
}

}  // namespace vesica::simulate
