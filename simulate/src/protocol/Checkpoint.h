#pragma once
// When a running cystometry writes its checkpoint (docs/simulate.md, "Checkpoint and
// resume"): every RunOptions::Checkpoints::interval_min minutes of compute, and when SIGTERM
// or SIGINT arrives, after which the run stops with the signal's conventional status
// (128 + signal). The handlers only set a flag (StopRequest.h): the Newton loop abandons
// the step in progress at its next iteration, and the checkpoint holds the last completed
// step. The file itself is CheckpointFile.h's. (A test stops a run at a known step through
// this real path by raising SIGTERM from its progress callback, RunOptions::on_progress.)
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "solver/StepStatistics.h"
#include "vesica/io/PvdSeries.h"
#include "vesica/simulate/protocol/CheckpointFile.h"
#include "vesica/simulate/protocol/Cystometry.h"

namespace vesica::simulate {

class Checkpointer {
 public:
  // Installs the SIGTERM/SIGINT handlers until destroyed (the earlier ones are restored).
  explicit Checkpointer(const RunOptions::Checkpoints& options);
  ~Checkpointer();
  Checkpointer(const Checkpointer&) = delete;
  Checkpointer& operator=(const Checkpointer&) = delete;

  // After a step that may be checkpointed: whether a checkpoint is due now.
  bool due() const;
  // Writes the state of a run standing at time_s (s) in `phase`.
  void write(const CheckpointWriter& state, double time_s, const std::string& phase);
  // The output folder's files so far (the series' frames), kept beside the checkpoint
  // (hard links) before it is written, and put back into a resumed run's output folder.
  void keep_outputs(const std::filesystem::path& output_dir) const;
  void restore_outputs(const std::filesystem::path& output_dir) const;
  // Throws RunInterrupted (Cystometry.h) when a stop signal has arrived (after its checkpoint, if
  // any).
  void stop_if_signalled() const;

 private:
  const RunOptions::Checkpoints& options_;
  std::chrono::steady_clock::time_point last_;
  double last_time_s_ = -1.0;  // of the last checkpoint written (s)
};

// A model's Newton counters in a checkpoint, and read back.
void put_statistics(CheckpointWriter& out, const std::string& name, const StepStatistics& s);
StepStatistics statistics_of(CheckpointReader& in, const std::string& name);

// A ParaView series' progress in a checkpoint (an empty one when series is null).
void put_series(CheckpointWriter& out, const std::string& name, const io::PvdSeries* series);
// Restores it into series (when not null).
void restore_series(CheckpointReader& in, const std::string& name, io::PvdSeries* series);

// The identity stored in a checkpoint for a run (options.identity) at time_s in phase.
nlohmann::json checkpoint_identity(const RunOptions::Checkpoints& options, double time_s,
                                   const std::string& phase);
// Reads options.file and checks that it belongs to this run (same inputs and
// parameters); throws vesica::Error naming the file otherwise.
CheckpointFile read_own_checkpoint(const RunOptions::Checkpoints& options);

}  // namespace vesica::simulate
