#include "vesica/compare/analysis/SimulatedModel.h"

#include <fstream>

#include <nlohmann/json.hpp>

#include "vesica/core/Error.h"
#include "vesica/simulate/ModelCardJson.h"

namespace vesica::compare {

SimulatedModel read_simulated_model(const std::filesystem::path& history) {
  SimulatedModel m;
  const std::filesystem::path summary = history.parent_path() / "summary.json";
  if (!std::filesystem::exists(summary)) {
    m.problem = "no summary.json beside " + history.filename().string();
    return m;
  }
  try {
    const simulate::ModelCard card = simulate::read_model_card(summary);
    m.card = card;
  } catch (const Error& e) {
    m.problem = e.what();
  }
  std::ifstream in(summary);
  const nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  if (j.is_object()) m.version = j.value("version", "");
  return m;
}

nlohmann::json to_json(const SimulatedModel& m) {
  return {{"model_card", m.card ? nlohmann::json(*m.card) : nlohmann::json()},
          {"voiding_drive",
           m.card ? nlohmann::json(simulate::voiding_drive_text(*m.card)) : nlohmann::json()},
          {"problem", m.problem},
          {"version", m.version}};
}

}  // namespace vesica::compare
