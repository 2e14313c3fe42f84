#pragma once
// A ParaView time series: "<folder>/<name>.pvd" listing "<folder>/<name>/step_NNNN.vtu",
// one VtuGrid (VtuFile.h, mm) per step with its time in seconds, also kept in the step's
// field data as "time_s" (beside whatever numbers the caller put there, such as
// "volume_ml" and "pdet_cmh2o"), so that ParaView and other readers show it. Every file is
// written atomically, and the .pvd last, so that it lists only finished steps.
// vesica-simulate writes the wall ("series", with view.py: ParaViewScript.h) and, at
// level 2, the urine ("fluid").
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vesica/io/ParaViewScript.h"
#include "vesica/io/VtuFile.h"

namespace vesica::io {

class PvdSeries {
 public:
  PvdSeries(std::filesystem::path folder, std::string name);

  void add_step(double time_s, VtuGrid frame);
  // Writes view.py beside the .pvd on finish(), opening the step of largest "volume_ml"
  // (the last step when the steps have none).
  void set_paraview_script(ParaViewColouring colouring) { colouring_ = std::move(colouring); }
  // Writes the .pvd (after the steps), then view.py when asked for.
  void finish();

  // Where the series stands: its steps (time in s, file relative to the .pvd), their field
  // names and the step of largest volume, so that a resumed simulation continues it with
  // the earlier steps' files back in place (vesica-simulate --resume).
  struct Progress {
    std::vector<std::pair<double, std::string>> steps;
    std::vector<std::string> fields;
    double largest_volume_ml = -1.0, largest_volume_time_s = 0.0;
  };
  Progress progress() const {
    return {steps_, fields_, largest_volume_ml_, largest_volume_time_s_};
  }
  void resume(Progress p) {
    steps_ = std::move(p.steps);
    fields_ = std::move(p.fields);
    largest_volume_ml_ = p.largest_volume_ml;
    largest_volume_time_s_ = p.largest_volume_time_s;
  }

  std::filesystem::path pvd_path() const { return folder_ / (name_ + ".pvd"); }
  std::filesystem::path steps_folder() const { return folder_ / name_; }

 private:
  std::filesystem::path folder_;
  std::string name_;
  std::vector<std::pair<double, std::string>> steps_;  // time (s), file relative to the .pvd
  std::vector<std::string> fields_;                    // field-data names of the steps
  double largest_volume_ml_ = -1.0, largest_volume_time_s_ = 0.0;
  std::optional<ParaViewColouring> colouring_;
};

// The .pvd collection text of (time in s, file relative to the .pvd) steps.
std::string pvd_text(const std::vector<std::pair<double, std::string>>& steps);

// The steps a .pvd lists, as (time in s, file relative to it); throws vesica::Error naming
// the file when it is not a VTK collection.
std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd);

}  // namespace vesica::io
