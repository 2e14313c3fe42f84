#pragma once
// The wall's time series for ParaView, written by vesica_io (vesica/io/PvdSeries.h):
// series.pvd listing series/step_NNNN.vtu, each the wall at one time with point data
// displacement_mm and cell data principal Cauchy stresses (kPa), membrane tensions (N/m),
// thickness_mm, principal stretches and region, and field data time_s, volume_ml and
// pdet_cmh2o; view.py beside series.pvd opens it in ParaView coloured by σ1. Coordinates
// in mm.
#include <filesystem>
#include <vector>

#include <Eigen/Dense>

#include "vesica/io/PvdSeries.h"
#include "vesica/simulate/wall/WallModel.h"
#include "vesica/simulate/wall/WallStress.h"

namespace vesica::simulate {

// The bladder's state at a step, written as the step's field data.
struct FrameState {
  double volume_ml = 0.0, pdet_cmh2o = 0.0;
};

class VtuSeriesWriter {
 public:
  // folder: where series.pvd, series/ and view.py go.
  explicit VtuSeriesWriter(std::filesystem::path folder);

  void add_step(double time_s, const FrameState& state, const WallModel& wall,
                const std::vector<Eigen::Vector3d>& x,
                const std::vector<MembraneStressOutput>& stresses);
  // Writes series.pvd (after the steps, so that it lists only finished files).
  void finish();

  std::filesystem::path pvd_path() const { return series_.pvd_path(); }
  io::PvdSeries& series() { return series_; }  // its progress, for checkpoints
  const io::PvdSeries& series() const { return series_; }
  std::filesystem::path series_folder() const { return series_.steps_folder(); }

 private:
  io::PvdSeries series_;
};

// One step of the series: the wall at positions x (m), with its stresses.
io::VtuGrid wall_frame(const WallModel& wall, const std::vector<Eigen::Vector3d>& x,
                       const std::vector<MembraneStressOutput>& stresses);

}  // namespace vesica::simulate
