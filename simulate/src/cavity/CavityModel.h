#pragma once
// What the cystometry protocol (CystometryProtocol.h) needs of a model of the bladder and
// its urine: to try ONE step (to a volume, or in time) and say whether it converged, and
// to report its state. The protocol owns everything else: the phases (settle, fill, hold,
// activate, void, stop), the time-dependent loads (Pabd, straining, the detrusor's
// activation curve), the urethra law and when it opens, validation, the bookkeeping of time,
// infused and voided volume, the history rows, the frames' schedule, the cut-backs of failed steps
// and the summary, and the hand-over of a void to a simpler level (LevelLadder.h). SI units
// throughout.
//
// Three models implement it: LumpedCavity (level 0: the wall's sphere-equivalent),
// HydrostaticCavity (level 1: the urine as an enclosed volume with a hydrostatic pressure)
// and fluid::NavierStokesCavity (level 2: the urine as a flow on its tetrahedra). Another
// model is one new class deriving from CavityModel: implement the pure virtual
// functions (try_volume_step, try_step and the state getters), override the defaulted ones
// where the model needs them, and run it with
//   CystometryProtocol(settings, options).run(model);   // or .run(model, &ladder)
// (to offer it in run_cystometry, add one case where Cystometry.cpp picks the model by
// RunOptions::level). tests/simulate/ProtocolTest.cpp drives such a model.
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <nlohmann/json.hpp>

#include "cavity/UrethraLaw.h"
#include "vesica/simulate/ModelCard.h"
#include "vesica/simulate/wall/WallModel.h"
#include "vesica/simulate/wall/WallStress.h"

namespace vesica::simulate {

class CheckpointWriter;
class CheckpointReader;
class MembraneProblem;

// The protocol's time-dependent loads at one instant.
struct ProtocolLoads {
  double pabd_pa = 0.0;     // abdominal pressure at the reference height, straining included
  double activation = 0.0;  // detrusor activation a(t) ∈ [0, 1] (docs/physics.md §7.2)
};

// One timed step the protocol asks of a model.
struct StepRequest {
  double dt_s = 0.0;        // its length
  double end_time_s = 0.0;  // the protocol's time at its end (for the model's logs)
  double inflow_m3_s = 0.0;
  const UrethraLaw* urethra = nullptr;  // the outlet law while voiding; null: closed
  ProtocolLoads loads;                  // at the end of the step
  // The protocol's bookkeeping before the step: a volume-controlled model's urine volume
  // at its end is start + infused + dt inflow − voided − (what leaves during the step).
  double infused_m3 = 0.0, voided_m3 = 0.0;
};

// What a simpler model carries on from when the protocol hands the voiding down a level
// (LevelLadder.h; docs/simulate.md, "Levels and their hand-overs"): the last converged state
// of the model that could not go on. One record for every hand-over (2 → 1, 1 → 0).
struct CarriedState {
  double volume_m3 = 0.0;        // the urine volume now
  double pves_pa = 0.0;          // the urine pressure at the reference point now
  double outflow_m3_s = 0.0;     // through the urethra now
  double start_volume_m3 = 0.0;  // when the clock started: the protocol's bookkeeping base
  ProtocolLoads loads;           // of the last converged step (Pabd, activation)
  // The last converged step: from this volume, this long (0: none known, e.g. right after
  // a hand-over); a rate-dependent wall starts its history from it.
  double volume_before_m3 = 0.0, dt_before_s = 0.0;
  std::vector<Eigen::Vector3d> wall_positions;  // per wall node (m)
  // The membrane wall's committed history (Maxwell branches, thickness guesses); null
  // where the model has none. Valid while the model it comes from lives.
  const MembraneProblem* wall_history = nullptr;
};

struct StepResult {
  bool converged = false;
  int iterations = 0;      // Newton iterations of the attempt
  double voided_m3 = 0.0;  // converged: the volume that left through the urethra in the step
  std::string failure;     // not converged: why
};

// How the protocol steps a model.
struct StepRules {
  int max_cutbacks = 12;         // halvings of a failed timed step before the run fails
  int max_settle_cutbacks = 12;  // the same for the steps to the start volume
  // A failed voiding step is not cut back below this (s): the detrusor's Hill rate makes
  // the wall a dashpot of stiffness ∝ 1/Δt, so much shorter steps are harder, not easier,
  // and a run used to grind on at nanosecond steps (docs/physics.md §3.7). 0: no floor.
  double min_cut_void_step_s = 1e-3;
  // Filling and holding steps: 0 = adaptive (from half of RunOptions::max_fill_step_ml's
  // time, growing 1.5x after a step of at most 6 iterations), else this fixed step (s).
  double fixed_fill_step_s = 0.0;
  // Voiding steps: 0 = adaptive (CystometryProtocol::next_void_step), else this fixed step.
  double fixed_void_step_s = 0.0;
  // Bounds of an adaptive voiding step (s); 0: the first step's size and
  // RunOptions::max_void_step_s.
  double min_void_step_s = 0.0, max_void_step_s = 0.0;
  // Adaptive voiding steps also follow the outflow's change and the Newton iterations, and
  // restart at the shortest step when the urethra opens (CystometryProtocol::next_void_step).
  bool void_step_follows_flow = false;
  // Volume an adaptive voiding step aims to drain (ml): of a taut wall at most, and of a
  // slack one; 0: RunOptions::max_void_step_ml and the protocol's own slack aim.
  double void_step_ml = 0.0, slack_void_step_ml = 0.0;
  double void_frame_interval_s = 1.0;  // frames while voiding (s)
};

class CavityModel {
 public:
  virtual ~CavityModel() = default;

  virtual StepRules rules() const { return {}; }

  // Settling, before the clock starts: whether the model must be stepped to the start
  // volume (m³) at all, and one quasi-static step to the enclosed volume V (m³) under the
  // given loads, no time passing. Not converged: the state is as before the attempt.
  virtual bool needs_settling(double /*start_volume_m3*/) const { return true; }
  virtual StepResult try_volume_step(double volume_m3, const ProtocolLoads& loads) = 0;
  // The protocol's clock starts (t = 0) at the model's present state.
  virtual void start_clock() {}
  // The urethra opens (Pves reached its opening pressure) with this law: the request's
  // urethra of every step from now on.
  virtual void urethra_opens(const UrethraLaw& /*urethra*/) {}
  // One timed step. Converged: the model has moved to its end. Not converged: the state is
  // as before the attempt, so that the protocol may retry a shorter step.
  virtual StepResult try_step(const StepRequest& step) = 0;
  // Its place on the ladder of levels (LevelLadder.h): 2, 1 or 0; -1: none (a model no
  // other carries on from, e.g. a test's).
  virtual int level() const { return -1; }
  // The last converged state, for the model one level down (LevelLadder.h).
  virtual CarriedState carried_state() const { return {}; }
  // A voiding step failed after all cut-backs and no level below took over: the note that
  // ends voiding there without failing the run (where the model cannot follow the wall any
  // further), or "" to fail.
  virtual std::string voiding_end_note(const std::string& /*failure*/) const { return ""; }

  // State.
  virtual double volume() const = 0;            // enclosed urine volume (m³)
  virtual double pves() const = 0;              // urine pressure at the reference point (Pa)
  virtual double outflow() const = 0;           // through the urethra now (m³/s)
  virtual double reference_volume() const = 0;  // of the stress-free wall (m³)
  virtual const WallModel& wall() const = 0;
  virtual std::vector<Eigen::Vector3d> wall_positions() const = 0;      // per wall node (m)
  virtual std::vector<MembraneStressOutput> wall_stresses() const = 0;  // per triangle
  virtual nlohmann::json statistics() const = 0;  // the summary's "newton" object

  // The model's own outputs: extra summary keys, frames of its own (the protocol writes
  // the wall's; write: this frame goes to the files), notes for the user since the last
  // call, and what the progress line adds to "filling 120 ml".
  virtual void add_summary(nlohmann::json& /*summary*/) const {}
  virtual void add_frame(double /*time_s*/, bool /*write*/) {}
  virtual void finish_frames() {}
  virtual std::vector<std::string> take_notes() { return {}; }
  virtual std::string progress_label() const { return ""; }

  // Checkpoints (docs/simulate.md, "Checkpoint and resume"): whether the model can save
  // its state between two steps so exactly that the run continues bit for bit, and the
  // save and restore (on a model built from the same wall, material and settings).
  virtual bool saves_state() const { return false; }
  virtual void save_state(CheckpointWriter& /*out*/) const {}
  virtual void restore_state(CheckpointReader& /*in*/) {}
};

}  // namespace vesica::simulate
