#pragma once
// One urodynamic recording (a measured cystometry + pressure-flow study, or a simulated
// history.csv) in clinical units, one entry per row of the source file. Channels that the
// file did not have are empty vectors; every present channel has one value per row. A
// table read off at volume steps (as papers print filling and voiding tables) has no time
// channel: its rows are indexed by the infused or voided volume.
#include <optional>
#include <string>
#include <vector>

namespace vesica::io {

struct Recording {
  std::string source;              // file it was read from (for messages)
  std::vector<int> line;           // 1-based line number of each row in the source file
  std::vector<double> time_s;      // seconds from the start of the recording
  std::vector<std::string> event;  // event label of the row ("" when none)
  std::vector<double> pves_cmh2o;
  std::vector<double> pabd_cmh2o;
  std::vector<double> pdet_recorded_cmh2o;  // the device's own Pdet channel, when present
  std::vector<double> flow_ml_s;
  std::vector<double> voided_ml;   // cumulative voided volume (flowmeter)
  std::vector<double> infused_ml;  // cumulative infused volume (pump)
  std::vector<double> volume_ml;   // bladder volume, when the file states it (simulation)

  // Rows of the recording: the length of its channels (the longest, should one be short).
  std::size_t rows() const;
  bool has_time() const { return !time_s.empty(); }

  // Pdet of row i: the recorded Pdet channel when present (the device subtracts the
  // unrounded signals), else Pves - Pabd.
  double pdet_cmh2o(std::size_t i) const;
  bool has_pdet() const;
  bool has_flow() const { return !flow_ml_s.empty(); }
  // Bladder volume before the first row when the file has no volume channel: 0 for a
  // cystometry (filling starts from the empty bladder), the capacity for a voiding table
  // that gives only the voided volume (set by the caller, who knows it).
  double start_volume_ml = 0.0;

  // Bladder volume of row i: the volume channel when present, else
  // start_volume_ml + infused - voided.
  double bladder_volume_ml(std::size_t i) const;
  bool has_volume() const;
  // Cumulative voided volume of row i: the voided channel, else the trapezoidal
  // integral of the flow channel, else 0.
  std::vector<double> voided_or_integrated_ml() const;
};

}  // namespace vesica::io
