#pragma once
// The urine flow for ParaView: fluid.pvd listing fluid/step_NNNN.vtu, each the
// tetrahedra at one time with point data velocity_mm_s, pressure_cmh2o and, when given,
// wall_shear_pa. Coordinates
// in mm (field data "units" = "mm"); every file written atomically.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

// One .vtu (ASCII XML); state as in FluidMesh.h (m/s, Pa), mesh positions in m;
// wall_shear_pa: per node (zero off the wall), written as point data wall_shear_pa.
std::string fluid_vtu_text(const FluidMesh& mesh, const Eigen::VectorXd& state,
                           const std::vector<Eigen::Vector3d>* wall_shear_pa = nullptr);

class FluidVtuSeries {
 public:
  // folder: where fluid.pvd and fluid/ go.
  explicit FluidVtuSeries(std::filesystem::path folder) : folder_(std::move(folder)) {}

  void add_step(double time_s, const FluidMesh& mesh, const Eigen::VectorXd& state,
                const std::vector<Eigen::Vector3d>* wall_shear_pa = nullptr);
  // Writes fluid.pvd after the steps, so that it lists only finished files.
  void finish();

  std::filesystem::path pvd_path() const { return folder_ / "fluid.pvd"; }

 private:
  std::filesystem::path folder_;
  std::vector<std::pair<double, std::string>> steps_;
};

}  // namespace vesica::simulate::fluid
