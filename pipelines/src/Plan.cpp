#include "vesica/pipelines/Plan.h"

#include <unistd.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

#include "vesica/core/Suggest.h"
#include "vesica/pipelines/ParameterCheck.h"
#include "vesica/pipelines/StudyExpansion.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {

const std::vector<std::string>& builtin_tools() {
  static const std::vector<std::string> tools = {"phantom", "segment",  "surface",
                                                 "mesh",    "simulate", "compare"};
  return tools;
}

fs::path own_bin_dir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? fs::current_path() : exe.parent_path();
}

std::string normal_path(const std::string& path) {
  std::string s = fs::path(path).lexically_normal().generic_string();
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}

namespace {

bool inside_or_equal(const std::string& path, const std::string& folder) {
  return path == folder ||
         (path.size() > folder.size() && path.compare(0, folder.size(), folder) == 0 &&
          path[folder.size()] == '/');
}

std::string dashed(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

std::string loc(const SourcePos& p) {
  return "line " + std::to_string(p.line);
}

// The file's stages resolved to workdir-relative paths, before any study expansion.
struct BaseStage {
  const StageSpec* spec = nullptr;
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string>> named;
  std::string output, report, manifest;
  std::vector<std::size_t> deps;  // indices into the base list
  std::vector<long> producer_of_positional, producer_of_named;
};

class Planner {
 public:
  Planner(const PipelineSpec& spec, const PlanOptions& options, Diagnostics& d)
      : spec_(spec), options_(options), d_(d) {
    plan_.name = spec.name;
    plan_.file = spec.file;
    plan_.question = spec.study.question;
    plan_.limits = spec.study.limits;
    const fs::path base = spec.file.parent_path();
    plan_.workdir = options.workdir_override.empty()
                        ? (base / spec.workdir).lexically_normal()
                        : fs::absolute(options.workdir_override).lexically_normal();
    for (const auto& e : spec.externals) {
      const fs::path abs = (base / e.path).lexically_normal();
      if (!fs::exists(abs))
        d_.add(e.pos, "external input '" + e.name + "' not found: " + abs.string());
      externals_[e.name] = abs;
    }
  }

  Plan build() {
    plan_.unchecked_tools = check_parameters(spec_, d_);
    resolve_stages();
    find_dependencies();
    check_duplicate_outputs();
    if (!d_.empty()) return plan_;
    const auto order = topological_order();
    if (order.empty()) return plan_;
    check_study();
    if (!d_.empty()) return plan_;
    expand(order);
    return plan_;
  }

 private:
  // "${inputs.ct}/x" -> path of the external input relative to the workdir.
  std::string resolve(const PathRef& ref) {
    std::string text = ref.text;
    for (std::size_t at = text.find("${"); at != std::string::npos; at = text.find("${", at)) {
      const auto end = text.find('}', at);
      if (end == std::string::npos) {
        d_.add(ref.pos, "unterminated '${' in '" + ref.text + "'");
        return text;
      }
      const std::string name = text.substr(at + 2, end - at - 2);
      const std::string prefix = "inputs.";
      std::string replacement;
      if (name.compare(0, prefix.size(), prefix) != 0) {
        d_.add(ref.pos, "unknown reference '${" + name + "}' (only ${inputs.NAME} is known)");
      } else if (auto it = externals_.find(name.substr(prefix.size())); it == externals_.end()) {
        std::vector<std::string> names;
        for (const auto& kv : externals_) names.push_back(kv.first);
        d_.add(ref.pos, "unknown external input '" + name.substr(prefix.size()) + "'" +
                            did_you_mean(name.substr(prefix.size()), names));
      } else {
        replacement = relative_to_workdir(it->second);
      }
      text.replace(at, end - at + 1, replacement);
      at += replacement.size();
    }
    return normal_path(text);
  }

  std::string relative_to_workdir(const fs::path& absolute) const {
    const fs::path rel = absolute.lexically_relative(plan_.workdir);
    return rel.empty() ? absolute.string() : rel.generic_string();
  }

  std::string own_path(const PathRef& ref, const std::string& what, const StageSpec& s) {
    const std::string p = normal_path(ref.text);
    if (fs::path(p).is_absolute() || p == ".." || p.compare(0, 3, "../") == 0)
      d_.add(ref.pos, "the " + what + " of stage '" + s.name +
                          "' must stay inside the workdir: " + ref.text);
    return p;
  }

  void resolve_stages() {
    std::vector<std::string> tools = builtin_tools();
    for (const auto& s : spec_.stages) {
      BaseStage b;
      b.spec = &s;
      for (const auto& in : s.positional) b.positional.push_back(resolve(in));
      for (const auto& [key, in] : s.named) b.named.push_back({key, resolve(in)});
      if (!s.output.text.empty()) {
        b.output = own_path(s.output, "output", s);
        const fs::path dir = fs::path(b.output).parent_path();
        b.report = s.report.text.empty() ? normal_path((dir / (s.name + ".json")).string())
                                         : own_path(s.report, "report", s);
        b.manifest = s.manifest.text.empty()
                         ? normal_path((dir / (s.name + ".manifest.json")).string())
                         : own_path(s.manifest, "manifest", s);
      }
      const bool known = std::count(tools.begin(), tools.end(), s.tool) > 0 ||
                         fs::exists(options_.bin_dir / ("vesica-" + s.tool));
      if (!known)
        d_.add(s.tool_pos, "unknown tool '" + s.tool + "' for stage '" + s.name + "'" +
                               did_you_mean(s.tool, tools));
      base_.push_back(std::move(b));
    }
  }

  long base_producer(const std::string& path) const {
    for (std::size_t i = 0; i < base_.size(); ++i)
      if (!base_[i].output.empty() &&
          (inside_or_equal(path, base_[i].output) || path == base_[i].report))
        return static_cast<long>(i);
    return -1;
  }

  // `external`: written as ${inputs.NAME}, whose existence was checked with the inputs.
  long link(BaseStage& b, const std::string& path, const PathRef& ref) {
    const SourcePos& pos = ref.pos;
    const bool external = ref.text.find("${") != std::string::npos;
    const long producer = base_producer(path);
    if (producer >= 0) {
      if (std::count(b.deps.begin(), b.deps.end(), producer) == 0)
        b.deps.push_back(static_cast<std::size_t>(producer));
    } else if (!external && !fs::exists((plan_.workdir / path).lexically_normal())) {
      d_.add(pos, "input '" + path + "' of stage '" + b.spec->name +
                      "' is not written by any stage and does not exist (looked in " +
                      plan_.workdir.string() + ")");
    }
    return producer;
  }

  void find_dependencies() {
    for (auto& b : base_) {
      for (std::size_t k = 0; k < b.positional.size(); ++k)
        b.producer_of_positional.push_back(link(b, b.positional[k], b.spec->positional[k]));
      for (std::size_t k = 0; k < b.named.size(); ++k)
        b.producer_of_named.push_back(link(b, b.named[k].second, b.spec->named[k].second));
    }
  }

  void check_duplicate_outputs() {
    struct Written {
      std::string path;
      const StageSpec* stage;
      SourcePos pos;
    };
    std::vector<Written> written;
    for (const auto& b : base_) {
      if (b.output.empty()) continue;
      const StageSpec& s = *b.spec;
      const Written mine[] = {
          {b.output, &s, s.output.pos},
          {b.report, &s, s.report.text.empty() ? s.output.pos : s.report.pos},
          {b.manifest, &s, s.manifest.text.empty() ? s.output.pos : s.manifest.pos}};
      for (const auto& w : mine) {
        for (const auto& other : written)
          if (inside_or_equal(w.path, other.path) || inside_or_equal(other.path, w.path)) {
            d_.add(w.pos, "output '" + w.path + "' of stage '" + s.name + "' collides with '" +
                              other.path + "' of stage '" + other.stage->name + "' (" +
                              loc(other.pos) + ")");
          }
        written.push_back(w);
      }
    }
  }

  // Kahn's algorithm in file order; on a cycle reports it and returns nothing.
  std::vector<std::size_t> topological_order() {
    const std::size_t n = base_.size();
    std::vector<int> state(n, 0);  // 0 new, 1 on stack, 2 done
    std::vector<std::size_t> order, stack;
    std::function<bool(std::size_t)> visit = [&](std::size_t i) {
      if (state[i] == 2) return true;
      if (state[i] == 1) {
        std::string cycle;
        auto from = std::find(stack.begin(), stack.end(), i);
        for (auto it = from; it != stack.end(); ++it) cycle += base_[*it].spec->name + " -> ";
        d_.add(base_[i].spec->pos, "stages form a cycle: " + cycle + base_[i].spec->name);
        return false;
      }
      state[i] = 1;
      stack.push_back(i);
      for (std::size_t d : base_[i].deps)
        if (!visit(d)) return false;
      stack.pop_back();
      state[i] = 2;
      order.push_back(i);
      return true;
    };
    for (std::size_t i = 0; i < n; ++i)
      if (!visit(i)) return {};
    return order;
  }

  void check_study() {
    std::vector<std::string> names;
    for (const auto& s : spec_.stages) names.push_back(s.name);
    auto check = [&](const std::string& stage, const SourcePos& pos) {
      if (!spec_.find_stage(stage))
        d_.add(pos, "study names unknown stage '" + stage + "'" + did_you_mean(stage, names));
    };
    for (const auto& axis : spec_.study.matrix) check(axis.stage, axis.pos);
    std::set<std::string> seen;
    for (const auto& v : spec_.study.variants) {
      if (!seen.insert(v.name).second) d_.add(v.pos, "variant '" + v.name + "' defined twice");
      for (const auto& o : v.overrides) check(o.stage, o.param.pos);
    }
  }

  void expand(const std::vector<std::size_t>& order) {
    std::vector<StudyRun> runs = expand_study(spec_.study);
    if (runs.empty()) runs.push_back({});
    std::map<std::size_t, std::size_t> shared;  // base index -> plan index
    for (const auto& run : runs) {
      std::vector<bool> varied(base_.size(), false);
      std::vector<std::size_t> planned(base_.size(), 0);
      for (std::size_t i : order) {
        const BaseStage& b = base_[i];
        varied[i] = run.overrides.count(b.spec->name) > 0;
        for (std::size_t d : b.deps) varied[i] = varied[i] || varied[d];
        if (!varied[i] && shared.count(i)) {
          planned[i] = shared[i];
          continue;
        }
        planned[i] = add_stage(b, varied[i] ? run : StudyRun{}, varied, planned);
        if (!varied[i]) shared[i] = planned[i];
      }
    }
  }

  std::size_t add_stage(const BaseStage& b, const StudyRun& run, const std::vector<bool>& varied,
                        const std::vector<std::size_t>& planned) {
    const StageSpec& s = *b.spec;
    const std::string prefix = run.name.empty() ? "" : "variants/" + run.name + "/";
    auto input = [&](const std::string& path, long producer) {
      return producer >= 0 && varied[static_cast<std::size_t>(producer)] ? prefix + path : path;
    };
    PlannedStage p;
    p.stage = s.name;
    p.variant = run.name;
    p.id = run.name.empty() ? s.name : s.name + "@" + run.name;
    p.tool = s.tool;
    p.executable = options_.bin_dir / ("vesica-" + s.tool);
    p.output = prefix + b.output;
    p.report = prefix + b.report;
    p.manifest = prefix + b.manifest;
    auto it = run.overrides.find(s.name);
    p.params = it == run.overrides.end() ? s.params : apply_overrides(s.params, it->second);
    for (std::size_t k = 0; k < b.positional.size(); ++k) {
      p.inputs.push_back(input(b.positional[k], b.producer_of_positional[k]));
      p.argv.push_back(p.inputs.back());
    }
    p.argv.insert(p.argv.end(), {"-o", p.output});
    for (std::size_t k = 0; k < b.named.size(); ++k) {
      p.inputs.push_back(input(b.named[k].second, b.producer_of_named[k]));
      p.argv.insert(p.argv.end(), {"--" + dashed(b.named[k].first), p.inputs.back()});
    }
    for (const auto& param : p.params) {
      if (param.kind == Param::Kind::Omitted) continue;
      p.argv.push_back("--" + dashed(param.key));
      if (param.kind == Param::Kind::Value) p.argv.push_back(param.value);
    }
    p.argv.insert(p.argv.end(), {"--report", p.report, "--manifest", p.manifest});
    for (std::size_t d : b.deps) p.deps.push_back(planned[d]);
    plan_.stages.push_back(std::move(p));
    return plan_.stages.size() - 1;
  }

  const PipelineSpec& spec_;
  const PlanOptions& options_;
  Diagnostics& d_;
  Plan plan_;
  std::map<std::string, fs::path> externals_;
  std::vector<BaseStage> base_;
};

}  // namespace

long Plan::index_of(const std::string& id) const {
  for (std::size_t i = 0; i < stages.size(); ++i)
    if (stages[i].id == id) return static_cast<long>(i);
  return -1;
}

long Plan::producer_of(const std::string& path) const {
  const std::string p = normal_path(path);
  for (std::size_t i = 0; i < stages.size(); ++i)
    if (inside_or_equal(p, stages[i].output) || p == stages[i].report) return static_cast<long>(i);
  return -1;
}

std::vector<std::size_t> Plan::downstream_of(std::size_t index) const {
  std::vector<bool> below(stages.size(), false);
  below[index] = true;
  std::vector<std::size_t> out;
  for (std::size_t i = index + 1; i < stages.size(); ++i)
    for (std::size_t d : stages[i].deps)
      if (below[d] && !below[i]) {
        below[i] = true;
        out.push_back(i);
      }
  return out;
}

fs::path Plan::in_workdir(const std::string& path) const {
  const fs::path p(path);
  return p.is_absolute() ? p : (workdir / p).lexically_normal();
}

Plan build_plan(const PipelineSpec& spec, const PlanOptions& options, Diagnostics& diagnostics) {
  return Planner(spec, options, diagnostics).build();
}

}  // namespace vesica::pipelines
