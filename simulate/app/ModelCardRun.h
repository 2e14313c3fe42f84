#pragma once
// vesica-simulate --model-card FILE: the run a model card describes (a calibration's
// fit/model.json, or a summary.json), kept beside main.cpp, which calls it before reading
// the mesh. The card replaces every model parameter; only what does not change the model
// (the series, the checkpoint interval, the FEBio export) may be given beside it.
#include <string>

#include <CLI/CLI.hpp>

#include "vesica/core/ParameterTable.h"
#include "vesica/simulate/ModelCard.h"
#include "vesica/simulate/SimulateSettings.h"

namespace vesica::simulate {

// Reads the card, refuses a model option given beside it (a usage error naming it) and
// puts the card's wall options, protocol and numerics into `settings`.
ModelCard settings_from_card_file(const std::string& file, const CLI::App& app,
                                  const ParameterTable& table, SimulateSettings& settings);

// Refuses a wall read from another mesh than the one the card ran on.
void check_card_mesh(const ModelCard& card, const WallModel& wall);

}  // namespace vesica::simulate
