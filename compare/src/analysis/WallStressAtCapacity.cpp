#include <algorithm>

#include <nlohmann/json.hpp>

#include "vesica/compare/analysis/WallStress.h"
#include "vesica/io/HistoryCsv.h"

namespace vesica::compare {

nlohmann::json wall_stress_at_capacity(const std::filesystem::path& simulation) {
  const std::filesystem::path pvd = simulation / "series.pvd";
  if (!std::filesystem::exists(pvd)) return nullptr;
  const io::Recording history = io::read_history_csv(simulation / "history.csv");
  std::size_t capacity = 0;
  for (std::size_t i = 1; i < history.rows(); ++i)
    if (history.bladder_volume_ml(i) > history.bladder_volume_ml(capacity)) capacity = i;
  const auto frame = frame_at_time(pvd, history.time_s[capacity]);
  if (!frame) return nullptr;
  const WallStressField field = read_wall_stress_field(*frame);
  nlohmann::json j = {{"frame", std::filesystem::relative(*frame, simulation).string()},
                      {"capacity_time_s", history.time_s[capacity]},
                      {"summary", to_json(summarize(field))},
                      {"projection", to_json(project_anterior(field))}};
  return j;
}

}  // namespace vesica::compare
