#pragma once
// The time series for ParaView: series.pvd listing series/step_NNNN.vtu, each the wall
// at one time with point data displacement_mm and cell data principal Cauchy stresses
// (kPa), membrane tensions (N/m), thickness_mm, principal stretches and region.
// Coordinates in mm (field data "units" = "mm"), every file written atomically.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "vesica/simulate/MembraneElement.h"
#include "vesica/simulate/WallModel.h"

namespace vesica::simulate {

class VtuSeriesWriter {
 public:
  // folder: where series.pvd and series/ go.
  explicit VtuSeriesWriter(std::filesystem::path folder);

  void add_step(double time_s, const WallModel& wall, const std::vector<Eigen::Vector3d>& x,
                const std::vector<MembraneStressOutput>& stresses);
  // Writes series.pvd (after the steps, so that it lists only finished files).
  void finish();

  std::filesystem::path pvd_path() const { return folder_ / "series.pvd"; }
  std::filesystem::path series_folder() const { return folder_ / "series"; }

 private:
  std::filesystem::path folder_;
  std::vector<std::pair<double, std::string>> steps_;
};

// One .vtu of the series (exposed for tests).
std::string wall_vtu_text(const WallModel& wall, const std::vector<Eigen::Vector3d>& x,
                          const std::vector<MembraneStressOutput>& stresses);

}  // namespace vesica::simulate
