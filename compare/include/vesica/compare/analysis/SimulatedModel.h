#pragma once
// The model a simulated recording came from, as its run recorded it: the model card
// (simulate's ModelCard.h) in the summary.json beside history.csv, and the vesica version
// that ran it. Nothing is guessed from a manifest, a file name or the curves: without a
// card the model is unknown, and the report says why.
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "vesica/simulate/ModelCard.h"

namespace vesica::compare {

struct SimulatedModel {
  std::optional<simulate::ModelCard> card;
  std::string problem;  // why there is no card: no summary.json, no card in it, a bad card
  std::string version;  // of the vesica that ran it ("" unknown)
};

SimulatedModel read_simulated_model(const std::filesystem::path& history_csv);

// For metrics.json: {"model_card": the card or null, "problem", "version",
// "voiding_drive": voiding_drive_text or null}.
nlohmann::json to_json(const SimulatedModel& model);

}  // namespace vesica::compare
