#pragma once
// The cystometry protocol (docs/physics.md §7), run once over any cavity model
// (CavityModel.h): settle to the start volume, fill at the infusion rate to capacity, hold,
// then activate the voiding drive (the detrusor's contraction, or abdominal straining,
// along ActivationCurve.h) and void through the urethra law (docs/physics.md §5), which
// opens and closes, until the flow stops. It owns the clock, the
// time-dependent loads, the infused and voided volumes, the history rows, the frames'
// schedule, the cut-backs of failed steps (halving up to the model's limit), the hand-over
// of a void a model cannot go on with to the level below (LevelLadder.h) and the summary;
// the model only steps and reports its state.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cavity/CavityModel.h"
#include "cavity/LevelLadder.h"
#include "cavity/UrethraLaw.h"
#include "protocol/ActivationCurve.h"
#include "vesica/simulate/protocol/CheckpointFile.h"
#include "vesica/simulate/protocol/Cystometry.h"

namespace vesica::simulate {

class VtuSeriesWriter;
class Checkpointer;
class CheckpointWriter;
class CheckpointReader;

class CystometryProtocol {
 public:
  // Keeps references to settings and options (validated: validate() in Cystometry.h).
  CystometryProtocol(const ProtocolSettings& settings, const RunOptions& options);
  ~CystometryProtocol();

  // Runs the whole protocol on the model and writes the wall's series when options ask
  // (history.csv is the caller's). With a ladder, a voiding step that fails after its
  // cut-backs with the urethra open hands the rest of the voiding to the level below
  // (hand_over); the result's card lists every hand-over. A step that fails otherwise ends
  // the run with completed = false and the history so far.
  CystometryResult run(CavityModel& model, const LevelLadder* ladder = nullptr);

  // Checkpoints (docs/simulate.md, "Checkpoint and resume"; CystometryProtocolState.cpp):
  // the protocol's state between two steps, the model's after it.
  void save_state(CheckpointWriter& out) const;
  void restore_state(CheckpointReader& in);

 private:
  struct StepFailed : std::runtime_error {
    using std::runtime_error::runtime_error;
  };

  void settle();
  void fill();
  void hold();
  void void_bladder();
  // Moves to volume V (m³) without time passing, halving the move on failure.
  // Returns how many cut-backs the move needed (0: it went in one step).
  int step_to_volume(double volume_m3);
  // One timed step of at most dt with inflow q_in (m³/s), the urethra open or closed,
  // halving dt on failure; throws StepFailed after the model's cut-backs.
  StepResult advance(double dt, double q_in, bool outlet);
  // The next adaptive voiding step from the one just taken (dt, draining dV, changing the
  // outflow by flow_change of itself, in Newton iterations).
  double next_void_step(double dt, double dV, double flow_change, int iterations) const;
  bool contraction_spent(double p_before) const;
  ProtocolLoads loads_at(double t) const;
  // The one place a run changes level: the model one level down carries on from the
  // present one's state; false where there is none.
  bool hand_over(const std::string& failure);
  void summarize_hand_overs(nlohmann::json& summary) const;
  std::string progress_label() const;
  void record();
  void frame(bool force);
  void take_notes();
  void summarize(double seconds);
  // Resumes from RunOptions::checkpoints when asked: true when the state was restored.
  bool resume_if_asked();
  // After a filling or holding step's row: writes a checkpoint when one is due, and stops
  // the run (RunInterrupted) when a signal asked for it.
  void checkpoint_if_due();
  // The checkpoint state of the run as it stands (filling or hold; none otherwise), and its
  // writing: a stop during a step writes the state taken before it.
  std::optional<CheckpointWriter> last_step_state() const;
  void write_checkpoint_of(const std::optional<CheckpointWriter>& state);

  const ProtocolSettings& settings_;
  const RunOptions& options_;
  const UrethraLaw urethra_;
  UrethraLaw urethra_now_ = urethra_;  // urethra_ as it recovers (physics.md §5), for one step
  double volume_at_opening_ = 0.0;     // m³
  const ActivationCurve activation_;
  CavityModel* model_ = nullptr;  // the model running now: top_ or the last of lower_
  CavityModel* top_ = nullptr;    // the model the run started with
  const LevelLadder* ladder_ = nullptr;
  std::vector<std::unique_ptr<CavityModel>> lower_;  // the levels handed down to, in order
  StepRules rules_;
  std::unique_ptr<VtuSeriesWriter> series_;
  CystometryResult result_;
  double time_ = 0.0, t_void_ = -1.0;            // s; t_void_ < 0: not voiding yet
  double infused_ = 0.0, voided_ = 0.0;          // since the start volume (m³)
  double start_volume_ = 0.0;                    // at t = 0 (m³)
  double mass_error_ = 0.0, max_stress_ = 0.0;   // relative; Pa
  double next_frame_ = 0.0, last_frame_ = -1.0;  // s
  double max_growth_ = 2.0;                      // of the next adaptive voiding step
  std::size_t capacity_index_ = 0;               // the last filling (or hold) row
  bool voiding_ = false, filled_ = false;
  bool urethra_open_ = false;
  double peak_pves_ = 0.0;                       // the highest Pves while voiding (Pa)
  std::map<std::string, double> phase_seconds_;  // wall-clock time of settle, filling, voiding
  // Where the run stands, for checkpoints: the phase, whether its loop continues from a
  // restored state, its present step (s) and the end of the hold (s).
  enum class Phase { Settle, Filling, Hold, Voiding };
  Phase phase_ = Phase::Settle;
  bool resuming_ = false;
  double step_s_ = 0.0, hold_end_s_ = 0.0;
  std::unique_ptr<Checkpointer> checkpointer_;  // null: no checkpoints
};

}  // namespace vesica::simulate
