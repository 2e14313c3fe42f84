#include "vesica/simulate/fluid/FluidVtuSeries.h"

#include "fluid/FlowStructures.h"
#include "protocol/SeriesFrames.h"
#include "vesica/core/Units.h"

namespace vesica::simulate::fluid {

io::VtuGrid fluid_frame(const FluidMesh& mesh, const Eigen::VectorXd& state,
                        const std::vector<Eigen::Vector3d>* wall_shear_pa,
                        const OutletAxis* outlet) {
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
  const std::vector<TetVortexMeasures> vortices = tet_vortex_measures(mesh, state);
  g.cell_data.push_back(frame_array("vorticity_1_s", 3, vortices.size(), [&](std::size_t e, int c) {
    return vortices[e].vorticity[c];
  }));
  g.cell_data.push_back(frame_array("q_criterion_1_s2", 1, vortices.size(),
                                    [&](std::size_t e, int) { return vortices[e].q_criterion; }));
  if (outlet) {
    g.field_data.push_back(frame_array("outlet_centroid_mm", 3, 1, [&](std::size_t, int c) {
      return units::mm_from_m(outlet->centroid_m[c]);
    }));
    g.field_data.push_back(
        frame_array("outlet_axis", 3, 1, [&](std::size_t, int c) { return outlet->direction[c]; }));
  }
  return g;
}

void FluidVtuSeries::add_step(double time_s, const FluidMesh& mesh, const Eigen::VectorXd& state,
                              const std::vector<Eigen::Vector3d>* wall_shear_pa,
                              const OutletAxis* outlet) {
  series_.add_step(time_s, fluid_frame(mesh, state, wall_shear_pa, outlet));
}

}  // namespace vesica::simulate::fluid
