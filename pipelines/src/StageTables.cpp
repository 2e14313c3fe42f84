#include "vesica/pipelines/StageTables.h"

#include "vesica/pipelines/StageTableList.h"

namespace vesica::pipelines {

std::optional<ParameterTable> stage_table(const std::string& tool) {
  const auto& tables = listed_stage_tables();
  const auto it = tables.find(tool);
  if (it == tables.end()) return std::nullopt;
  return it->second();
}

std::vector<std::string> tools_with_tables() {
  std::vector<std::string> tools;
  for (const auto& entry : listed_stage_tables()) tools.push_back(entry.first);
  return tools;
}

const std::vector<std::string>& tools_without_tables() {
  // Every shipped tool has its table now. A tool added without one is listed here, so that
  // `vesica validate` names it (its `params` would reach it unchecked) instead of staying silent.
  static const std::vector<std::string> tools = {};
  return tools;
}

}  // namespace vesica::pipelines
