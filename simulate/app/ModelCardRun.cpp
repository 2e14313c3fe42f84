// vesica-simulate --model-card (ModelCardRun.h).
#include "ModelCardRun.h"

#include <algorithm>

#include "vesica/core/Error.h"
#include "vesica/simulate/ModelCardJson.h"

namespace vesica::simulate {
namespace {

// The options that change no model: where and how often outputs are written.
const char* const kBesideACard[] = {"no_series", "checkpoint_minutes", "export_feb"};

void refuse_model_options(const CLI::App& app, const ParameterTable& table) {
  for (const Parameter& p : table.entries()) {
    if (p.kind == Parameter::Kind::Input || app.count(p.option()) == 0) continue;
    if (std::find(std::begin(kBesideACard), std::end(kBesideACard), p.name) !=
        std::end(kBesideACard))
      continue;
    usage_error(p.option() + " cannot be given with --model-card: the card sets the model",
                "edit the card, or leave --model-card out");
  }
}

}  // namespace

ModelCard settings_from_card_file(const std::string& file, const CLI::App& app,
                                  const ParameterTable& table, SimulateSettings& s) {
  refuse_model_options(app, table);
  const ModelCard card = read_model_card(file);
  // In place: the table's entries are bound to these fields. The card's material comes
  // whole from the card (material_spec of its MaterialCard), none from the table.
  s.material.name = card.material.name;
  for (auto& [name, value] : s.material.values) value = kMaterialDefault;
  for (auto& [name, list] : s.material.branches) list.clear();
  s.wall = card.wall;
  s.protocol = card.protocol;
  s.posture = card.protocol.posture;
  apply_numerics(card.numerics, s.run);
  s.run.reference = card.wall.reference;
  return card;
}

void check_card_mesh(const ModelCard& card, const WallModel& wall) {
  if (card.mesh.hash.empty() || card.mesh.hash == wall.source_hash) return;
  usage_error(wall.source_file + " is not the mesh the model card ran on (" + card.mesh.file +
                  ", " + card.mesh.hash + ")",
              "give that mesh, or calibrate on this one");
}

}  // namespace vesica::simulate
