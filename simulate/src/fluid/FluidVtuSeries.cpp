#include "vesica/simulate/fluid/FluidVtuSeries.h"

#include <cstdio>
#include <sstream>

#include "../VtkXmlText.h"
#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Units.h"

namespace vesica::simulate::fluid {
namespace {

constexpr int kVtkTetra = 10;

}  // namespace

std::string fluid_vtu_text(const FluidMesh& mesh, const Eigen::VectorXd& state,
                           const std::vector<Eigen::Vector3d>* wall_shear_pa) {
  std::ostringstream s;
  s.precision(9);
  const std::size_t nn = mesh.nodes.size();
  vtu_mesh_mm(s, mesh.nodes, mesh.tets, kVtkTetra);
  s << "<PointData Vectors=\"velocity_mm_s\" Scalars=\"pressure_cmh2o\">\n";
  vtk_data_array(s, "Float64", "velocity_mm_s", 3, nn, [&](std::size_t i, int c) {
    return units::mm_from_m(state[kDofsPerNode * i + c]);
  });
  vtk_data_array(s, "Float64", "pressure_cmh2o", 1, nn, [&](std::size_t i, int) {
    return units::cmh2o_from_pa(state[kDofsPerNode * i + 3]);
  });
  if (wall_shear_pa)
    vtk_data_array(s, "Float64", "wall_shear_pa", 3, nn,
                   [&](std::size_t i, int c) { return (*wall_shear_pa)[i][c]; });
  s << "</PointData>\n";
  vtu_end(s);
  return s.str();
}

void FluidVtuSeries::add_step(double time_s, const FluidMesh& mesh, const Eigen::VectorXd& state,
                              const std::vector<Eigen::Vector3d>* wall_shear_pa) {
  char name[32];
  std::snprintf(name, sizeof name, "step_%04zu.vtu", steps_.size());
  write_text_atomically(folder_ / "fluid" / name, fluid_vtu_text(mesh, state, wall_shear_pa));
  steps_.emplace_back(time_s, std::string("fluid/") + name);
}

void FluidVtuSeries::finish() {
  write_text_atomically(pvd_path(), pvd_text(steps_));
}

}  // namespace vesica::simulate::fluid
