#include "vesica/pipelines/ParameterCheck.h"

#include <algorithm>

#include "vesica/core/Suggest.h"
#include "vesica/pipelines/StageTables.h"

namespace vesica::pipelines {
namespace {

using Kind = Parameter::Kind;

// "simulate", or "sim (vesica-simulate)" when the stage is named apart from its tool.
std::string stage_label(const StageSpec& s) {
  return s.name == s.tool ? s.name : s.name + " (vesica-" + s.tool + ")";
}

Parameter* entry_named(ParameterTable& table, const std::string& name) {
  for (Parameter& p : table.entries())
    if (p.name == name) return &p;
  return nullptr;
}

void check_value(const Param& param, Parameter& entry, const std::string& who, Diagnostics& d) {
  const std::string what = "parameter '" + param.key + "' of " + who;
  if (entry.kind == Kind::Flag) {
    // The runner turns `true` into a bare flag; a quoted 'true' would be a stray value.
    if (param.kind == Param::Kind::Value)
      d.add(param.pos,
            what + " is a flag: write true or false (unquoted), not '" + param.value + "'");
    return;
  }
  if (param.kind != Param::Kind::Value) {
    d.add(param.pos, what + " takes a value (" + entry.accepted() + "), not " +
                         (param.kind == Param::Kind::Flag ? "true" : "false"));
    return;
  }
  try {
    entry.assign(param.value);
  } catch (const ParameterValueError& e) {
    d.add(param.pos, what + ": " + e.what());
  }
}

void check_param(const Param& param, ParameterTable& table, const std::string& who,
                 Diagnostics& d) {
  Parameter* entry = entry_named(table, param.key);
  if (!entry) {
    const auto names =
        table.names({Kind::Number, Kind::Integer, Kind::Flag, Kind::Choice, Kind::Text});
    d.add(param.key_pos,
          "unknown parameter '" + param.key + "' for " + who + did_you_mean(param.key, names));
  } else if (entry->kind == Kind::Input) {
    d.add(param.key_pos,
          "'" + param.key + "' is an input of " + who + ": give it under 'inputs:', not 'params:'");
  } else {
    check_value(param, *entry, who, d);
  }
}

void check_named_inputs(const StageSpec& s, const ParameterTable& table, Diagnostics& d) {
  for (const auto& [key, ref] : s.named) {
    const Parameter* entry = table.find(key);
    if (entry && entry->kind == Kind::Input) continue;
    if (entry)
      d.add(ref.pos, "'" + key + "' is a parameter of " + stage_label(s) +
                         ": give it under 'params:', not 'inputs:'");
    else
      d.add(ref.pos, "unknown input '" + key + "' for " + stage_label(s) +
                         did_you_mean(key, table.names({Kind::Input})));
  }
}

// Each study value on its own, against default settings: a study run combines values
// that are each valid.
void check_study(const PipelineSpec& spec, Diagnostics& d) {
  auto check = [&](const std::string& stage, const Param& param) {
    const StageSpec* s = spec.find_stage(stage);  // an unknown stage is the planner's report
    if (!s) return;
    if (auto table = stage_table(s->tool)) check_param(param, *table, stage_label(*s), d);
  };
  for (const auto& axis : spec.study.matrix)
    for (const auto& value : axis.values) check(axis.stage, value);
  for (const auto& variant : spec.study.variants)
    for (const auto& o : variant.overrides) check(o.stage, o.param);
}

}  // namespace

std::vector<std::string> check_parameters(const PipelineSpec& spec, Diagnostics& d) {
  std::vector<std::string> unchecked;
  for (const auto& s : spec.stages) {
    std::optional<ParameterTable> table = stage_table(s.tool);
    if (!table) {
      if (std::count(unchecked.begin(), unchecked.end(), s.tool) == 0) unchecked.push_back(s.tool);
      continue;
    }
    for (const auto& param : s.params) check_param(param, *table, stage_label(s), d);
    check_named_inputs(s, *table, d);
  }
  check_study(spec, d);
  return unchecked;
}

}  // namespace vesica::pipelines
