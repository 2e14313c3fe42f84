#pragma once
// A ParaView time series: "<folder>/<name>.pvd" listing "<folder>/<name>/step_NNNN.vtu",
// one VtuGrid (VtuFile.h, mm) per step with its time in seconds. Every file is written
// atomically, and the .pvd last, so that it lists only finished steps. vesica-simulate
// writes the wall ("series") and, at level 2, the urine ("fluid").
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "vesica/io/VtuFile.h"

namespace vesica::io {

class PvdSeries {
 public:
  PvdSeries(std::filesystem::path folder, std::string name);

  void add_step(double time_s, const VtuGrid& frame);
  // Writes the .pvd (after the steps).
  void finish();

  std::filesystem::path pvd_path() const { return folder_ / (name_ + ".pvd"); }
  std::filesystem::path steps_folder() const { return folder_ / name_; }

 private:
  std::filesystem::path folder_;
  std::string name_;
  std::vector<std::pair<double, std::string>> steps_;  // time (s), file relative to the .pvd
};

// The .pvd collection text of (time in s, file relative to the .pvd) steps.
std::string pvd_text(const std::vector<std::pair<double, std::string>>& steps);

// The steps a .pvd lists, as (time in s, file relative to it); throws vesica::Error naming
// the file when it is not a VTK collection.
std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd);

}  // namespace vesica::io
