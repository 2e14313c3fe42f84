#pragma once
// The model a calibration fits, seen as a function: a vector of parameter values (in the
// units of the FitParameters, same order) gives one simulated cystometry. The two-stage
// fit (TwoStageFit.h) calls a fast surrogate and the reported model through this one
// signature, so that a new model is wired in without touching the fit.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "vesica/compare/recording/Recording.h"
#include "vesica/simulate/ModelCard.h"

namespace vesica::compare {

struct ModelRun {
  Recording recording;             // the run's history (time, volumes, pressures, flow)
  bool completed = false;          // reached the end of its protocol
  std::string failure;             // why not ("step failed at t = .. s, V = .. ml: ...")
  std::vector<std::string> notes;  // the simulation's notes (e.g. a tail of voiding at level 0)
  std::optional<simulate::ModelCard> card;  // what ran, when a simulator's run says it
};

using ModelSimulator = std::function<ModelRun(const std::vector<double>& values)>;

}  // namespace vesica::compare
