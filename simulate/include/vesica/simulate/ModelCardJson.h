#pragma once
// The model card (ModelCard.h) as JSON: the one place that turns it into text and back.
// Units are in the key names (SI for the material, the clinical units of the parameter
// table for the rest, as summary.json has them); enums as their parameter-table words.
// Layout (format "vesica model card 1"):
//   {"format", "material": {name, mu_pa, k_pa, beta_vol, fibers: {k1_pa, k2} | null,
//    maxwell_branches: [{beta, tau_s}], muscle: {tone_pa, contractility_pa, ...}},
//    "reference": {kind, residual_ml, image_pressure_cmh2o, volume_ml, mean_thickness_mm,
//    thickness_mm, fixed_patch_radius_mm}, "protocol": {...filling and surroundings}, "voiding": {drive,
//    straining_kpa, activation: {...}, abdominal_pressure: resting | recorded,
//    recorded_pabd: {time_s, cmh2o}}, "urethra": {law, p_open_cmh2o, ...}, "level":
//    {started, hand_overs: [{from, to, volume_ml, time_s, reason}]}, "numerics": {...},
//    "mesh": {file, hash, triangles, nodes, tetrahedra, mean_edge_mm}}
// from_json refuses (vesica::Error naming the key) a card without a key it needs or with a
// value of the wrong kind, so that a hand-edited card never runs half-read.
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "vesica/simulate/ModelCard.h"

namespace vesica::simulate {

inline constexpr const char* kModelCardFormat = "vesica model card 1";

void to_json(nlohmann::json& j, const ModelCard& card);
void from_json(const nlohmann::json& j, ModelCard& card);

// The card as indented JSON text (model.json), and read back from such text; `source`
// names the text in errors.
std::string model_card_text(const ModelCard& card);
ModelCard model_card_from_text(const std::string& text, const std::string& source);

// A card file (fit/model.json) or a summary.json holding one under "model_card"; throws
// vesica::Error naming the file when it is missing, too large, not JSON or not a card.
ModelCard read_model_card(const std::filesystem::path& path);

}  // namespace vesica::simulate
