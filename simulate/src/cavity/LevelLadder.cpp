#include "cavity/LevelLadder.h"

#include <stdexcept>

#include "cavity/HydrostaticCavity.h"
#include "cavity/LumpedCavity.h"
#include "vesica/core/Log.h"

namespace vesica::simulate {

LevelLadder::LevelLadder(const WallModel& wall, const Material& material,
                         const ProtocolSettings& settings, const RunOptions& options)
    : wall_(wall), material_(material), settings_(settings), options_(options) {}

std::string level_name(int level) {
  switch (level) {
    case 2:
      return "the Navier-Stokes urine (level 2)";
    case 1:
      return "the hydrostatic urine on the membrane wall (level 1)";
    case 0:
      return "the wall's sphere-equivalent (level 0)";
    default:
      return "a model off the ladder";
  }
}

namespace {

// Why a level hands its void down, in the words of the model card.
std::string hand_over_reason(const CavityModel& from, const CarriedState& state,
                             const std::string& failure) {
  // Level 2's tetrahedra cannot follow a slack wall that folds inwards (docs/navier-stokes.md
  // §8): the usual reason there, and worth naming.
  if (from.level() == 2 && state.volume_m3 < from.reference_volume())
    return "below the stress-free volume the slack wall folds into the urine mesh (" + failure +
           ")";
  return "the wall could not take a voiding step (" + failure + ")";
}

}  // namespace

LevelLadder::Step LevelLadder::below(const CavityModel& from, const std::string& failure) const {
  if (from.level() < 1) return {};
  const CarriedState state = from.carried_state();
  Step step;
  try {
    if (from.level() == 2) {
      auto level1 = std::make_unique<HydrostaticCavity>(wall_, material_, settings_, options_);
      level1->continue_from(state);
      step.model = std::move(level1);
    } else {
      auto level0 = std::make_unique<LumpedCavity>(wall_, material_, settings_);
      level0->take_over(state);
      step.model = std::move(level0);
    }
  } catch (const std::runtime_error& e) {
    vesica::log()->debug("no hand-over from level {}: {}", from.level(), e.what());
    return {};
  }
  step.reason = hand_over_reason(from, state, failure);
  return step;
}

}  // namespace vesica::simulate
