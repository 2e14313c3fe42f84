#pragma once
// The ladder of cavity models (docs/simulate.md, "Levels and their hand-overs"): level 2
// (Navier–Stokes urine), level 1 (hydrostatic urine on the membrane wall) and level 0 (the
// wall's sphere-equivalent). When a voiding step fails after its cut-backs with the urethra
// open, the protocol (CystometryProtocol.h, the one place that decides a hand-over) asks the
// ladder for the model one level down, carrying on from the failing model's state
// (CavityModel.h); the reason it gives is the hand-over's on the model card.
#include <memory>
#include <string>

#include "cavity/CavityModel.h"
#include "vesica/simulate/protocol/CystometrySettings.h"

namespace vesica::simulate {

class Material;

class LevelLadder {
 public:
  // Keeps references to wall, material, settings and options (those the run's model was
  // built from).
  LevelLadder(const WallModel& wall, const Material& material, const ProtocolSettings& settings,
              const RunOptions& options);
  virtual ~LevelLadder() = default;

  struct Step {
    std::unique_ptr<CavityModel> model;  // null: no level below, or it cannot take over
    std::string reason;                  // why the hand-over happens, for the card
  };
  // The model one level below `from` (level 2 → 1 → 0), continuing from its last converged
  // state with the clock running; `failure` is why from's voiding step failed.
  // (Virtual for tests that stand in for a level.)
  virtual Step below(const CavityModel& from, const std::string& failure) const;

 private:
  const WallModel& wall_;
  const Material& material_;
  const ProtocolSettings& settings_;
  const RunOptions& options_;
};

// What a level is, for notes and progress lines: "Navier–Stokes urine (level 2)".
std::string level_name(int level);

}  // namespace vesica::simulate
