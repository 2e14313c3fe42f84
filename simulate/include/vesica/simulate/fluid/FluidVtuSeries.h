#pragma once
// The urine flow for ParaView, written by vesica_io (vesica/io/PvdSeries.h): fluid.pvd
// listing fluid/step_NNNN.vtu, each the tetrahedra at one time with point data
// velocity_mm_s, pressure_cmh2o and, when given, wall_shear_pa; cell data vorticity_1_s
// (∇ × u, 1/s) and q_criterion_1_s2 (½(‖W‖² − ‖S‖²), 1/s²: vortex cores where > 0); and,
// when given, field data outlet_centroid_mm and outlet_axis (unit, out of the bladder) of
// the urethra's patch, where the report cuts the jet. Coordinates in mm.
#include <filesystem>
#include <vector>

#include <Eigen/Dense>

#include "vesica/io/PvdSeries.h"
#include "vesica/simulate/fluid/FluidMesh.h"

namespace vesica::simulate::fluid {

// The urethra's outlet patch: its area-weighted centroid (m) and mean outward normal.
struct OutletAxis {
  Eigen::Vector3d centroid_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  // unit, out of the bladder
};

// One step: state as in FluidMesh.h (m/s, Pa), mesh positions in m; wall_shear_pa: per
// node (zero off the wall), written as point data wall_shear_pa.
io::VtuGrid fluid_frame(const FluidMesh& mesh, const Eigen::VectorXd& state,
                        const std::vector<Eigen::Vector3d>* wall_shear_pa = nullptr,
                        const OutletAxis* outlet = nullptr);

class FluidVtuSeries {
 public:
  // folder: where fluid.pvd and fluid/ go.
  explicit FluidVtuSeries(std::filesystem::path folder) : series_(std::move(folder), "fluid") {}

  void add_step(double time_s, const FluidMesh& mesh, const Eigen::VectorXd& state,
                const std::vector<Eigen::Vector3d>* wall_shear_pa = nullptr,
                const OutletAxis* outlet = nullptr);
  // Writes fluid.pvd after the steps, so that it lists only finished files.
  void finish() { series_.finish(); }

  std::filesystem::path pvd_path() const { return series_.pvd_path(); }
  io::PvdSeries& series() { return series_; }  // its progress, for checkpoints
  const io::PvdSeries& series() const { return series_; }

 private:
  io::PvdSeries series_;
};

}  // namespace vesica::simulate::fluid
