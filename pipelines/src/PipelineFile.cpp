#include "vesica/pipelines/PipelineFile.h"

#include <yaml-cpp/yaml.h>

#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"
#include "vesica/core/Suggest.h"
#include "vesica/pipelines/StudyMetrics.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

// A pipeline file is a page or two of YAML; a study of thousands of variants still fits.
constexpr std::uintmax_t kMaxPipelineFileBytes = std::uintmax_t{4} << 20;

const std::vector<std::string> kTopKeys = {"pipeline", "workdir", "inputs", "stages", "study"};
const std::vector<std::string> kStageKeys = {"tool",   "input",    "inputs", "output",
                                             "report", "manifest", "params"};
const std::vector<std::string> kStudyKeys = {"matrix",   "variants", "uncertainty",
                                             "max_runs", "question", "limits"};
const std::vector<std::string> kLimitKeys = {"min", "max"};

SourcePos pos_of(const YAML::Node& node) {
  const YAML::Mark m = node.Mark();
  if (m.is_null()) return {};
  return {m.line + 1, m.column + 1};
}

SourcePos pos_of(const YAML::Mark& m) {
  return {m.line + 1, m.column + 1};
}

const char* type_name(const YAML::Node& n) {
  switch (n.Type()) {
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Scalar:
      return "a value";
    default:
      return "empty";
  }
}

// Loads one document and reports problems against the original file's positions.
class Reader {
 public:
  Reader(const fs::path& file, Diagnostics& d) : d_(d) { spec_.file = file; }

  PipelineSpec read(const YAML::Node& root) {
    if (!root.IsMap()) {
      d_.add(pos_of(root),
             std::string("the pipeline file must be a map, found ") + type_name(root));
      return spec_;
    }
    for (const auto& kv : root) {
      std::string key;
      if (!key_text(kv.first, key)) continue;
      const YAML::Node& v = kv.second;
      if (key == "pipeline") {
        if (scalar(v, "pipeline")) spec_.name = v.as<std::string>();
      } else if (key == "workdir") {
        if (scalar(v, "workdir")) {
          spec_.workdir = v.as<std::string>();
          spec_.workdir_pos = pos_of(v);
        }
      } else if (key == "inputs") {
        read_externals(v);
      } else if (key == "stages") {
        read_stages(v);
      } else if (key == "study") {
        read_study(v);
      } else {
        unknown(kv.first, key, kTopKeys, "top-level key");
      }
    }
    if (!root["stages"]) d_.add({1, 1}, "the pipeline has no 'stages'");
    if (spec_.name.empty()) spec_.name = spec_.file.stem().string();
    return spec_;
  }

 private:
  void unknown(const YAML::Node& key_node, const std::string& key,
               const std::vector<std::string>& known, const std::string& what) {
    d_.add(pos_of(key_node), "unknown " + what + " '" + key + "'" + did_you_mean(key, known));
  }

  // A map key as text. A list or a map used as a key is reported at its place (yaml-cpp
  // would throw a conversion error that names neither the file nor the line).
  bool key_text(const YAML::Node& key_node, std::string& key) {
    if (key_node.IsScalar()) {
      key = key_node.Scalar();
      return true;
    }
    d_.add(pos_of(key_node),
           std::string("a key must be a plain name, found ") + type_name(key_node));
    return false;
  }

  bool scalar(const YAML::Node& v, const std::string& what) {
    if (v.IsScalar()) return true;
    d_.add(pos_of(v), "'" + what + "' must be a single value, found " + type_name(v));
    return false;
  }

  bool map(const YAML::Node& v, const std::string& what) {
    if (v.IsMap()) return true;
    d_.add(pos_of(v), "'" + what + "' must be a map, found " + type_name(v));
    return false;
  }

  void read_externals(const YAML::Node& v) {
    if (!map(v, "inputs")) return;
    for (const auto& kv : v) {
      std::string name;
      if (key_text(kv.first, name) && scalar(kv.second, "inputs." + name))
        spec_.externals.push_back({name, kv.second.as<std::string>(), pos_of(kv.second)});
    }
  }

  void read_stages(const YAML::Node& v) {
    if (!map(v, "stages")) return;
    for (const auto& kv : v) {
      StageSpec s;
      if (!key_text(kv.first, s.name)) continue;
      s.pos = pos_of(kv.first);
      s.tool = s.name;
      s.tool_pos = s.pos;
      if (spec_.find_stage(s.name)) d_.add(s.pos, "stage '" + s.name + "' is defined twice");
      if (s.name.find_first_of("@/ ") != std::string::npos)
        d_.add(s.pos, "stage name '" + s.name + "' may not contain '@', '/' or spaces");
      if (map(kv.second, "stages." + s.name)) read_stage(kv.second, s);
      spec_.stages.push_back(std::move(s));
    }
  }

  void read_stage(const YAML::Node& v, StageSpec& s) {
    for (const auto& kv : v) {
      std::string key;
      if (!key_text(kv.first, key)) continue;
      const YAML::Node& x = kv.second;
      const std::string where = s.name + "." + key;
      if (key == "tool") {
        if (scalar(x, where)) {
          s.tool = x.as<std::string>();
          s.tool_pos = pos_of(x);
        }
      } else if (key == "input") {
        read_positional(x, where, s);
      } else if (key == "inputs") {
        if (map(x, where))
          for (const auto& in : x) {
            std::string name;
            if (key_text(in.first, name) &&
                scalar(in.second, std::string(where).append(".").append(name)))
              s.named.push_back({name, {in.second.as<std::string>(), pos_of(in.second)}});
          }
      } else if (key == "output" || key == "report" || key == "manifest") {
        if (scalar(x, where)) {
          PathRef& target = key == "output" ? s.output : key == "report" ? s.report : s.manifest;
          target = {x.as<std::string>(), pos_of(x)};
        }
      } else if (key == "params") {
        if (map(x, where))
          for (const auto& p : x) {
            Param param;
            std::string name;
            if (key_text(p.first, name) &&
                read_param(name, pos_of(p.first), p.second, where, param))
              s.params.push_back(param);
          }
      } else {
        unknown(kv.first, key, kStageKeys, "stage key");
      }
    }
    if (s.output.text.empty()) d_.add(s.pos, "stage '" + s.name + "' has no 'output'");
  }

  void read_positional(const YAML::Node& x, const std::string& where, StageSpec& s) {
    if (x.IsScalar()) {
      s.positional.push_back({x.as<std::string>(), pos_of(x)});
    } else if (x.IsSequence()) {
      for (const auto& item : x)
        if (scalar(item, where)) s.positional.push_back({item.as<std::string>(), pos_of(item)});
    } else {
      d_.add(pos_of(x), "'" + where + "' must be a path or a list of paths, found " + type_name(x));
    }
  }

  // Plain (unquoted) true/false become a bare flag or nothing; quoted stays a value.
  static bool is_plain(const YAML::Node& x) { return x.Tag() == "?"; }

  bool read_param(const std::string& key, SourcePos key_pos, const YAML::Node& x,
                  const std::string& where, Param& param) {
    param.key = key;
    param.key_pos = key_pos;
    param.pos = pos_of(x);
    if (x.IsScalar()) {
      const std::string text = x.as<std::string>();
      if (is_plain(x) && (text == "true" || text == "True" || text == "TRUE")) {
        param.kind = Param::Kind::Flag;
      } else if (is_plain(x) && (text == "false" || text == "False" || text == "FALSE")) {
        param.kind = Param::Kind::Omitted;
      } else {
        param.value = text;
      }
      return true;
    }
    if (x.IsSequence()) {
      for (const auto& item : x) {
        if (!scalar(item, std::string(where).append(".").append(key))) return false;
        if (!param.value.empty()) param.value += ",";
        param.value += item.as<std::string>();
      }
      return true;
    }
    d_.add(pos_of(x), "parameter '" + where + "." + key +
                          "' must be a value or a list of values, found " + type_name(x));
    return false;
  }

  // "stage.param" -> (stage, param); false (and a diagnostic) when malformed.
  bool split_stage_param(const YAML::Node& key_node, std::string& stage, std::string& param) {
    std::string key;
    if (!key_text(key_node, key)) return false;
    const auto dot = key.find('.');
    if (dot == std::string::npos || dot == 0 || dot + 1 == key.size()) {
      d_.add(pos_of(key_node), "study key '" + key + "' must be written stage.param");
      return false;
    }
    stage = key.substr(0, dot);
    param = key.substr(dot + 1);
    return true;
  }

  void read_study(const YAML::Node& v) {
    if (!map(v, "study")) return;
    spec_.study.pos = pos_of(v);
    for (const auto& kv : v) {
      std::string key;
      if (!key_text(kv.first, key)) continue;
      if (key == "matrix") {
        read_matrix(kv.second);
      } else if (key == "variants") {
        read_named_overrides(kv.second, "study.variants", spec_.study.variants);
      } else if (key == "uncertainty") {
        read_named_overrides(kv.second, "study.uncertainty", spec_.study.uncertainty);
      } else if (key == "question") {
        if (scalar(kv.second, "study.question")) spec_.study.question = kv.second.as<std::string>();
      } else if (key == "limits") {
        read_limits(kv.second);
      } else if (key == "max_runs") {
        read_max_runs(kv.second);
      } else {
        unknown(kv.first, key, kStudyKeys, "study key");
      }
    }
  }

  void read_max_runs(const YAML::Node& v) {
    spec_.study.max_runs_pos = pos_of(v);
    try {
      if (v.IsScalar()) spec_.study.max_runs = v.as<long long>();
    } catch (const YAML::Exception&) {
      spec_.study.max_runs = 0;
    }
    if (spec_.study.max_runs <= 0)
      d_.add(pos_of(v), "'study.max_runs' must be a whole number of runs above 0");
  }

  void read_matrix(const YAML::Node& v) {
    if (!map(v, "study.matrix")) return;
    for (const auto& kv : v) {
      MatrixAxis axis;
      std::string param;
      axis.pos = pos_of(kv.first);
      if (!split_stage_param(kv.first, axis.stage, param)) continue;
      if (!kv.second.IsSequence() || kv.second.size() == 0) {
        d_.add(pos_of(kv.second),
               "study.matrix." + axis.stage + "." + param + " must be a non-empty list of values");
        continue;
      }
      for (const auto& item : kv.second) {
        Param p;
        if (read_param(param, axis.pos, item, "study.matrix." + axis.stage, p))
          axis.values.push_back(p);
      }
      spec_.study.matrix.push_back(axis);
    }
  }

  // metric: {min: A, max: B}, each bound optional, metric a study read-out.
  void read_limits(const YAML::Node& v) {
    if (!map(v, "study.limits")) return;
    for (const auto& kv : v) {
      StudyLimit limit;
      limit.metric = kv.first.as<std::string>();
      limit.pos = pos_of(kv.first);
      if (!find_study_metric(limit.metric)) {
        unknown(kv.first, limit.metric, study_metric_keys(), "study read-out");
        continue;
      }
      if (!map(kv.second, "study.limits." + limit.metric)) continue;
      for (const auto& bound : kv.second) {
        const std::string key = bound.first.as<std::string>();
        if (key != "min" && key != "max") {
          unknown(bound.first, key, kLimitKeys, "limit key");
          continue;
        }
        double value = 0.0;
        if (!bound.second.IsScalar() || !YAML::convert<double>::decode(bound.second, value)) {
          d_.add(pos_of(bound.second),
                 "study.limits." + limit.metric + "." + key + " must be a number");
          continue;
        }
        (key == "min" ? limit.min : limit.max) = value;
      }
      if (limit.min || limit.max) spec_.study.limits.push_back(limit);
    }
  }

  // `variants:` and `uncertainty:`: name -> {stage.param: value, ...} (or nothing).
  void read_named_overrides(const YAML::Node& v, const std::string& where,
                            std::vector<Variant>& out) {
    if (!map(v, where)) return;
    for (const auto& kv : v) {
      Variant variant;
      if (!key_text(kv.first, variant.name)) continue;
      variant.pos = pos_of(kv.first);
      if (variant.name.find_first_of("/@ ") != std::string::npos)
        d_.add(variant.pos,
               "name '" + variant.name + "' in " + where + " may not contain '/', '@' or spaces");
      if (!kv.second.IsNull() && !map(kv.second, where + "." + variant.name)) continue;
      if (kv.second.IsMap())
        for (const auto& o : kv.second) {
          Override ov;
          std::string param;
          if (!split_stage_param(o.first, ov.stage, param)) continue;
          if (read_param(param, pos_of(o.first), o.second, where + "." + variant.name, ov.param))
            variant.overrides.push_back(ov);
        }
      out.push_back(variant);
    }
  }

  Diagnostics& d_;
  PipelineSpec spec_;
};

}  // namespace

const StageSpec* PipelineSpec::find_stage(const std::string& stage_name) const {
  // Stages are only ever appended, so the index is complete when it has every stage.
  for (; indexed_ < stages.size(); ++indexed_)
    stage_index_.emplace(stages[indexed_].name, indexed_);
  const auto it = stage_index_.find(stage_name);
  return it == stage_index_.end() ? nullptr : &stages[it->second];
}

PipelineSpec parse_pipeline_text(const std::string& text, const fs::path& file,
                                 Diagnostics& diagnostics) {
  try {
    return Reader(file, diagnostics).read(YAML::Load(text));
  } catch (const YAML::ParserException& e) {
    diagnostics.add(pos_of(e.mark), "malformed YAML: " + e.msg);
  } catch (const YAML::Exception& e) {  // what the reader's checks did not foresee
    diagnostics.add(pos_of(e.mark), "malformed pipeline file: " + e.msg);
  }
  PipelineSpec empty;
  empty.file = file;
  return empty;
}

PipelineSpec load_pipeline_file(const fs::path& file, Diagnostics& diagnostics) {
  const fs::path absolute = fs::absolute(file).lexically_normal();
  std::string text;
  try {
    text = read_input_file(absolute, kMaxPipelineFileBytes, "pipeline file");
  } catch (const Error& e) {
    diagnostics.add({}, "cannot be read: " + e.problem());
    PipelineSpec empty;
    empty.file = absolute;
    return empty;
  }
  return parse_pipeline_text(text, absolute, diagnostics);
}

}  // namespace vesica::pipelines
