#include "vesica/simulate/fluid/FluidVtuSeries.h"

#include "../SeriesFrames.h"
#include "vesica/core/Units.h"

namespace vesica::simulate::fluid {

io::VtuGrid fluid_frame(const FluidMesh& mesh, const Eigen::VectorXd& state,
                        const std::vector<Eigen::Vector3d>* wall_shear_pa) {
  io::VtuGrid g;
  g.points_mm = points_mm(mesh.nodes);
  g.tets = cell_matrix(mesh.tets);
  const std::size_t nn = mesh.nodes.size();
  g.point_data.push_back(frame_array("velocity_mm_s", 3, nn, [&](std::size_t i, int c) {
    return units::mm_from_m(state[kDofsPerNode * i + c]);
  }));
  g.point_data.push_back(frame_array("pressure_cmh2o", 1, nn, [&](std::size_t i, int) {
    return units::cmh2o_from_pa(state[kDofsPerNode * i + 3]);
  }));
  if (wall_shear_pa)
    g.point_data.push_back(frame_array(
        "wall_shear_pa", 3, nn, [&](std::size_t i, int c) { return (*wall_shear_pa)[i][c]; }));
  return g;
}

void FluidVtuSeries::add_step(double time_s, const FluidMesh& mesh, const Eigen::VectorXd& state,
                              const std::vector<Eigen::Vector3d>* wall_shear_pa) {
  series_.add_step(time_s, fluid_frame(mesh, state, wall_shear_pa));
}

}  // namespace vesica::simulate::fluid
