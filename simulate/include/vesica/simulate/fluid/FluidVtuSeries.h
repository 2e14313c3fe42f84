#pragma once
// The urine flow for ParaView, written by vesica_io (vesica/io/PvdSeries.h): fluid.pvd
// listing fluid/step_NNNN.vtu, each the tetrahedra at one time with point data
// velocity_mm_s, pressure_cmh2o and, when given, wall_shear_pa. Coordinates in mm.
#include <filesystem>
#include <vector>

#include <Eigen/Dense>

#include "vesica/io/PvdSeries.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

// One step: state as in FluidMesh.h (m/s, Pa), mesh positions in m; wall_shear_pa: per
// node (zero off the wall), written as point data wall_shear_pa.
io::VtuGrid fluid_frame(const FluidMesh& mesh, const Eigen::VectorXd& state,
                        const std::vector<Eigen::Vector3d>* wall_shear_pa = nullptr);

class FluidVtuSeries {
 public:
  // folder: where fluid.pvd and fluid/ go.
  explicit FluidVtuSeries(std::filesystem::path folder) : series_(std::move(folder), "fluid") {}

  void add_step(double time_s, const FluidMesh& mesh, const Eigen::VectorXd& state,
                const std::vector<Eigen::Vector3d>* wall_shear_pa = nullptr);
  // Writes fluid.pvd after the steps, so that it lists only finished files.
  void finish() { series_.finish(); }

  std::filesystem::path pvd_path() const { return series_.pvd_path(); }
  io::PvdSeries& series() { return series_; }  // its progress, for checkpoints
  const io::PvdSeries& series() const { return series_; }

 private:
  io::PvdSeries series_;
};

}  // namespace vesica::simulate::fluid
