#include "vesica/pipelines/Plan.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <unordered_map>

#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"
#include "vesica/core/Suggest.h"
#include "vesica/pipelines/ParameterCheck.h"
#include "vesica/pipelines/PathIndex.h"
#include "vesica/pipelines/StageTables.h"
#include "vesica/pipelines/StateFolder.h"
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

// A pipeline installed with vesica (<prefix>/share/vesica/pipelines, beside <prefix>/bin):
// its own workdir would be under /usr/share, which a user cannot write and root should not.
bool is_installed_pipeline(const fs::path& file, const fs::path& bin_dir) {
  std::error_code ec;
  const fs::path installed = bin_dir / ".." / "share" / "vesica" / "pipelines";
  return fs::equivalent(fs::absolute(file).parent_path(), installed, ec) && !ec;
}

std::string dashed(std::string key) {
  std::replace(key.begin(), key.end(), '_', '-');
  return key;
}

std::string loc(const SourcePos& p) {
  return "line " + std::to_string(p.line);
}

// A path no file system can hold (a name over 255 bytes, a path over 4095): every later
// look at it (exists, status) would throw ENAMETOOLONG instead of answering, so it is a
// problem of the pipeline file, reported with its line. Empty when it fits.
std::string unholdable(const fs::path& p) {
  constexpr std::size_t kMaxName = 255, kMaxPath = 4095;
  if (p.native().size() > kMaxPath)
    return "a path of " + std::to_string(p.native().size()) + " characters (at most " +
           std::to_string(kMaxPath) + ")";
  for (const fs::path& part : p)
    if (part.native().size() > kMaxName)
      return "a name of " + std::to_string(part.native().size()) + " characters (at most " +
             std::to_string(kMaxName) + ")";
  return "";
}

// The file's stages resolved to workdir-relative paths, before any study expansion.
// A file a stage writes besides its output, report and manifest: a side output its tool
// declares (bladder.vtu beside bladder.msh) or a parameter naming a file (export_feb).
struct SideFile {
  std::string path;   // workdir-relative
  SourcePos pos;      // of the output, or of the parameter's value
  std::string param;  // the parameter's key; empty for a declared side output
};

struct BaseStage {
  const StageSpec* spec = nullptr;
  std::vector<std::string> positional;
  std::vector<std::pair<std::string, std::string>> named;
  std::string output, report, manifest;
  std::vector<SideFile> side;
  bool default_report = false, default_manifest = false;  // in .vesica/, named by the id
  std::vector<std::size_t> deps;                          // indices into the base list
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
    if (!options.workdir_override.empty())
      plan_.workdir = fs::absolute(options.workdir_override).lexically_normal();
    else if (is_installed_pipeline(spec.file, options.bin_dir))
      plan_.workdir = (fs::current_path() / spec.name).lexically_normal();
    else
      plan_.workdir = (base / spec.workdir).lexically_normal();
    for (const auto& e : spec.externals) {
      const fs::path abs = (base / e.path).lexically_normal();
      if (const std::string why = unholdable(abs); !why.empty())
        d_.add(e.pos, "external input '" + e.name + "' is " + why);
      else if (std::error_code ec; !fs::exists(abs, ec))
        d_.add(e.pos, "external input '" + e.name + "' not found: " + abs.string() +
                          (ec ? " (" + ec.message() + ")" : ""));
      else if (is_special_file(abs))
        d_.add(e.pos, "external input '" + e.name + "' is a named pipe, device or socket, " +
                          "not a file a stage can read: " + abs.string());
      externals_[e.name] = abs;
    }
  }

  Plan build() {
    plan_.unchecked_tools = check_parameters(spec_, d_);
    resolve_stages();
    find_dependencies();
    check_duplicate_outputs();
    check_output_places();
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
    std::string p = normal_path(ref.text);
    if (fs::path(p).is_absolute() || p == ".." || p.compare(0, 3, "../") == 0)
      d_.add(ref.pos, "the " + what + " of stage '" + s.name +
                          "' must stay inside the workdir: " + ref.text);
    else if (what != "report" && what != "manifest" && state::is_state_path(p))
      d_.add(ref.pos, "the " + what + " of stage '" + s.name + "' may not be inside " +
                          state::kFolder + "/, vesica's own folder: " + ref.text);
    return p;
  }

  // What the stage's tool writes beside its output (its table's side outputs), and the files
  // its parameters name for writing, each checked to stay inside the workdir as the output.
  std::vector<SideFile> side_files(const StageSpec& s, const std::string& output) {
    std::vector<SideFile> files;
    const std::optional<ParameterTable> table = stage_table(s.tool);
    if (!table) return files;
    for (const std::string& path : table->side_outputs(output))
      files.push_back({normal_path(path), s.output.pos, ""});
    for (const Param& p : s.params) {
      const Parameter* entry = table->find(p.key);
      if (!entry || !entry->names_output || p.kind != Param::Kind::Value || p.value.empty())
        continue;
      files.push_back({own_path({p.value, p.pos}, p.key, s), p.pos, p.key});
    }
    return files;
  }

  bool known_tool(const std::string& tool) {
    const auto it = known_tools_.find(tool);
    if (it != known_tools_.end()) return it->second;
    const auto& builtin = builtin_tools();
    // A tool is a program beside `vesica`: a plain name (no path, no dots), and a file name
    // the system can hold (a longer one makes the lookup itself fail).
    const bool plain = !tool.empty() && tool.size() <= 64 &&
                       std::all_of(tool.begin(), tool.end(), [](unsigned char c) {
                         return std::isalnum(c) || c == '_' || c == '-';
                       });
    std::error_code ec;
    const bool known = std::count(builtin.begin(), builtin.end(), tool) > 0 ||
                       (plain && fs::exists(options_.bin_dir / ("vesica-" + tool), ec));
    return known_tools_[tool] = known;
  }

  void resolve_stages() {
    for (const auto& s : spec_.stages) {
      BaseStage b;
      b.spec = &s;
      for (const auto& in : s.positional) b.positional.push_back(resolve(in));
      for (const auto& [key, in] : s.named) b.named.push_back({key, resolve(in)});
      if (!s.output.text.empty()) {
        b.output = own_path(s.output, "output", s);
        b.default_report = s.report.text.empty();
        b.default_manifest = s.manifest.text.empty();
        b.report = b.default_report ? state::report_path(s.name) : own_path(s.report, "report", s);
        b.manifest =
            b.default_manifest ? state::manifest_path(s.name) : own_path(s.manifest, "manifest", s);
        outputs_.add(b.output, static_cast<long>(base_.size()));
        reports_.emplace(b.report, static_cast<long>(base_.size()));
        b.side = side_files(s, b.output);
        for (const SideFile& f : b.side) outputs_.add(f.path, static_cast<long>(base_.size()));
      }
      if (!known_tool(s.tool))
        d_.add(s.tool_pos, "unknown tool '" + s.tool + "' for stage '" + s.name + "'" +
                               did_you_mean(s.tool, builtin_tools()));
      base_.push_back(std::move(b));
    }
  }

  // The stage whose output is or holds `path`, or whose report it is; -1 for none.
  long base_producer(const std::string& path) const {
    const long holder = outputs_.holder_of(path);
    if (holder >= 0) return holder;
    const auto report = reports_.find(path);
    return report == reports_.end() ? -1 : report->second;
  }

  // `external`: written as ${inputs.NAME}, whose existence was checked with the inputs.
  long link(std::size_t self, const std::string& path, const PathRef& ref) {
    BaseStage& b = base_[self];
    const SourcePos& pos = ref.pos;
    const bool external = ref.text.find("${") != std::string::npos;
    const long producer = base_producer(path);
    if (producer == static_cast<long>(self)) {
      d_.add(pos, "input '" + path + "' of stage '" + b.spec->name + "' is its own output '" +
                      b.output + "': a stage would replace what it reads");
      return -1;
    }
    if (const std::string why = unholdable(plan_.workdir / path); !why.empty()) {
      d_.add(pos, "input of stage '" + b.spec->name + "' is " + why);
      return -1;
    }
    if (producer >= 0) {
      if (std::count(b.deps.begin(), b.deps.end(), producer) == 0)
        b.deps.push_back(static_cast<std::size_t>(producer));
    } else if (std::error_code ec;
               !external && !fs::exists((plan_.workdir / path).lexically_normal(), ec)) {
      d_.add(pos, "input '" + path + "' of stage '" + b.spec->name +
                      "' is not written by any stage and does not exist (looked in " +
                      plan_.workdir.string() + ")");
    } else if (!external && is_special_file((plan_.workdir / path).lexically_normal())) {
      d_.add(pos, "input '" + path + "' of stage '" + b.spec->name +
                      "' is a named pipe, device or socket, not a file a stage can read");
    }
    return producer;
  }

  void find_dependencies() {
    for (std::size_t i = 0; i < base_.size(); ++i) {
      BaseStage& b = base_[i];
      for (std::size_t k = 0; k < b.positional.size(); ++k)
        b.producer_of_positional.push_back(link(i, b.positional[k], b.spec->positional[k]));
      for (std::size_t k = 0; k < b.named.size(); ++k)
        b.producer_of_named.push_back(link(i, b.named[k].second, b.spec->named[k].second));
    }
  }

  struct Written {
    std::string path;
    const StageSpec* stage;
    SourcePos pos;
  };

  // The paths a stage writes: output, report, manifest, with the line each comes from.
  static std::vector<Written> written_by(const BaseStage& b) {
    const StageSpec& s = *b.spec;
    std::vector<Written> w = {{b.output, &s, s.output.pos},
                              {b.report, &s, b.default_report ? s.output.pos : s.report.pos},
                              {b.manifest, &s, b.default_manifest ? s.output.pos : s.manifest.pos}};
    for (const SideFile& f : b.side) w.push_back({f.path, &s, f.pos});
    return w;
  }

  void check_duplicate_outputs() {
    std::vector<Written> written;
    PathIndex index;  // path -> index into `written`
    for (const auto& b : base_) {
      if (b.output.empty()) continue;
      for (const auto& w : written_by(b)) {
        if (w.path == ".") continue;  // the workdir itself: check_output_places says so
        long other = index.holder_of(w.path);
        if (other < 0) other = index.inside(w.path).second;
        if (other >= 0) {
          const Written& o = written[static_cast<std::size_t>(other)];
          d_.add(w.pos, "output '" + w.path + "' of stage '" + w.stage->name + "' collides with '" +
                            o.path + "' of stage '" + o.stage->name + "' (" + loc(o.pos) + ")");
        }
        index.add(w.path, static_cast<long>(written.size()));
        written.push_back(w);
      }
    }
  }

  // What a written path would replace that is not vesica's to replace (a stage's output
  // replaces what is at its place): the workdir, the pipeline file, an external input, or a
  // folder holding one of them. (An input inside an output is that stage's product, and a
  // stage reading its own output is reported with its inputs.)
  std::string replaces_what(const std::string& path) const {
    if (path == ".") return "is the workdir";
    const std::string file = normal_path(plan_.file.lexically_relative(plan_.workdir).string());
    if (!file.empty() && file.compare(0, 2, "..") != 0 && inside_or_equal(file, path))
      return (file == path ? "is" : "holds") + std::string(" the pipeline file ") + file;
    for (const auto& [name, abs] : externals_) {
      const std::string rel = normal_path(abs.lexically_relative(plan_.workdir).string());
      if (rel.empty() || rel.compare(0, 2, "..") == 0 || !inside_or_equal(rel, path)) continue;
      std::string what = rel == path ? "is" : "holds";
      return what.append(" the external input '")
          .append(name)
          .append("' (")
          .append(rel)
          .append(")");
    }
    return "";
  }

  void check_output_places() {
    for (const auto& b : base_) {
      if (b.output.empty()) continue;
      for (const auto& w : written_by(b)) {
        if (const std::string why = unholdable(plan_.workdir / w.path); !why.empty()) {
          d_.add(w.pos, "output of stage '" + w.stage->name + "' is " + why);
          continue;
        }
        const std::string what = replaces_what(w.path);
        if (!what.empty())
          d_.add(w.pos, "output '" + w.path + "' of stage '" + w.stage->name + "' " + what +
                            "; vesica replaces what is at an output's place, so it must be a "
                            "file or folder of its own");
      }
    }
  }

  // Depth-first in file order, iterative so that a long chain of stages cannot exhaust the
  // call stack; on a cycle reports it and returns nothing.
  std::vector<std::size_t> topological_order() {
    const std::size_t n = base_.size();
    std::vector<int> state(n, 0);  // 0 new, 1 on the path, 2 done
    std::vector<std::size_t> order;
    std::vector<std::pair<std::size_t, std::size_t>> path;  // (stage, next dependency)
    order.reserve(n);
    for (std::size_t root = 0; root < n; ++root) {
      if (state[root] != 0) continue;
      state[root] = 1;
      path.push_back({root, 0});
      while (!path.empty()) {
        const std::size_t i = path.back().first;
        if (path.back().second == base_[i].deps.size()) {
          state[i] = 2;
          order.push_back(i);
          path.pop_back();
          continue;
        }
        const std::size_t d = base_[i].deps[path.back().second++];
        if (state[d] == 1) {
          report_cycle(path, d);
          return {};
        }
        if (state[d] == 0) {
          state[d] = 1;
          path.push_back({d, 0});
        }
      }
    }
    return order;
  }

  void report_cycle(const std::vector<std::pair<std::size_t, std::size_t>>& path, std::size_t d) {
    std::string cycle;
    auto from = std::find_if(path.begin(), path.end(), [&](const auto& p) { return p.first == d; });
    for (auto it = from; it != path.end(); ++it) cycle += base_[it->first].spec->name + " -> ";
    d_.add(base_[d].spec->pos, "stages form a cycle: " + cycle + base_[d].spec->name);
  }

  void check_study() {
    auto check = [&](const std::string& stage, const SourcePos& pos) {
      if (spec_.find_stage(stage)) return;
      std::vector<std::string> names;
      for (const auto& s : spec_.stages) names.push_back(s.name);
      d_.add(pos, "study names unknown stage '" + stage + "'" + did_you_mean(stage, names));
    };
    const long long runs = study_run_count(spec_.study);
    if (runs > spec_.study.max_runs)
      d_.add(
          spec_.study.pos,
          "the study expands to " +
              (runs == kTooManyRuns ? "more than " + std::to_string(runs) : std::to_string(runs)) +
              " runs, more than study.max_runs (" + std::to_string(spec_.study.max_runs) +
              "): set max_runs if you mean it");
    for (const auto& axis : spec_.study.matrix) check(axis.stage, axis.pos);
    std::set<std::string> seen;
    for (const auto& v : spec_.study.variants) {
      if (!seen.insert(v.name).second) d_.add(v.pos, "variant '" + v.name + "' defined twice");
      for (const auto& o : v.overrides) check(o.stage, o.param.pos);
    }
    std::set<std::string> ends;
    for (const auto& v : spec_.study.uncertainty) {
      if (!ends.insert(v.name).second)
        d_.add(v.pos, "uncertainty end '" + v.name + "' defined twice");
      if (v.overrides.empty())
        d_.add(v.pos, "uncertainty end '" + v.name + "' changes no parameter");
      for (const auto& o : v.overrides) check(o.stage, o.param.pos);
    }
  }

  void expand(const std::vector<std::size_t>& order) {
    std::vector<StudyRun> runs = expand_study(spec_.study);
    if (runs.empty()) runs.push_back({});
    std::map<std::size_t, std::size_t> shared;  // base index -> plan index
    // Per ordinary run: which base stages it varies and the copy it uses of each.
    std::map<std::string, std::pair<std::vector<bool>, std::vector<std::size_t>>> by_run;
    // A stage only an uncertainty end varies is copied once per end, whatever run it bounds.
    std::map<std::pair<std::string, std::size_t>, std::size_t> end_only;
    for (const auto& run : runs) {
      std::vector<bool> varied(base_.size(), false);
      std::vector<std::size_t> planned(base_.size(), 0);
      const bool is_bound = !run.bound.empty();
      const auto* parent = is_bound ? &by_run[run.bound_of] : nullptr;
      for (std::size_t i : order) {
        const BaseStage& b = base_[i];
        varied[i] = run.overrides.count(b.spec->name) > 0;
        for (std::size_t d : b.deps) varied[i] = varied[i] || varied[d];
        if (!varied[i] && shared.count(i)) {
          planned[i] = shared[i];
          continue;
        }
        if (is_bound) {
          bool by_end = run.bound_overrides.count(b.spec->name) > 0;
          for (std::size_t d : b.deps)
            by_end = by_end || plan_.stages[planned[d]].bound == run.bound;
          if (!by_end) {  // the bounded run's own copy
            planned[i] = parent->second[i];
            continue;
          }
          if (!parent->first[i]) {  // varied by the end alone
            const auto key = std::make_pair(run.bound, i);
            if (!end_only.count(key)) {
              StudyRun only;
              only.name = run.bound;
              only.bound = run.bound;
              only.overrides = run.bound_overrides;
              end_only[key] = add_stage(b, only, planned);
            }
            planned[i] = end_only[key];
            continue;
          }
        }
        planned[i] = add_stage(b, varied[i] ? run : StudyRun{}, planned);
        if (!varied[i]) shared[i] = planned[i];
      }
      if (!is_bound) by_run[run.name] = {varied, planned};
    }
  }

  // `planned` holds the copies this run reads from: an input a stage copy writes is read
  // from that copy's folder.
  std::size_t add_stage(const BaseStage& b, const StudyRun& run,
                        const std::vector<std::size_t>& planned) {
    const StageSpec& s = *b.spec;
    const std::string prefix = run.name.empty() ? "" : "variants/" + run.name + "/";
    auto input = [&](const std::string& path, long producer) {
      if (producer < 0) return path;
      const std::string& v = plan_.stages[planned[static_cast<std::size_t>(producer)]].variant;
      return v.empty() ? path : "variants/" + v + "/" + path;
    };
    PlannedStage p;
    p.stage = s.name;
    p.variant = run.name;
    p.bound = run.bound;
    p.bound_of = run.bound_of;
    p.id = run.name.empty() ? s.name : s.name + "@" + run.name;
    p.tool = s.tool;
    p.executable = options_.bin_dir / ("vesica-" + s.tool);
    p.output = prefix + b.output;
    p.report = b.default_report ? state::report_path(p.id) : prefix + b.report;
    p.manifest = b.default_manifest ? state::manifest_path(p.id) : prefix + b.manifest;
    auto it = run.overrides.find(s.name);
    p.params = it == run.overrides.end() ? s.params : apply_overrides(s.params, it->second);
    for (const SideFile& f : b.side) {
      p.side_outputs.push_back(prefix + f.path);
      // A file a parameter names is the variant's own, as its output is.
      for (Param& param : p.params)
        if (!f.param.empty() && param.key == f.param) param.value = prefix + f.path;
    }
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
  PathIndex outputs_;                              // output -> base index
  std::unordered_map<std::string, long> reports_;  // report -> base index
  std::map<std::string, bool> known_tools_;
};

}  // namespace

long Plan::index_of(const std::string& id) const {
  for (std::size_t i = 0; i < stages.size(); ++i)
    if (stages[i].id == id) return static_cast<long>(i);
  return -1;
}

std::vector<std::size_t> Plan::named(const std::string& name) const {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < stages.size(); ++i)
    if (stages[i].id == name || stages[i].stage == name) out.push_back(i);
  if (out.empty()) {
    std::vector<std::string> ids;
    for (const auto& s : stages) ids.push_back(s.id);
    usage_error("no stage named '" + name + "'" + did_you_mean(name, ids));
  }
  return out;
}

long Plan::producer_of(const std::string& path) const {
  if (indexed_ != stages.size()) {
    producers_ = std::make_shared<Producers>();
    for (std::size_t i = 0; i < stages.size(); ++i) {
      producers_->outputs.add(stages[i].output, static_cast<long>(i));
      for (const std::string& side : stages[i].side_outputs)
        producers_->outputs.add(side, static_cast<long>(i));
      producers_->reports.emplace(stages[i].report, static_cast<long>(i));
    }
    indexed_ = stages.size();
  }
  const std::string p = normal_path(path);
  const long holder = producers_->outputs.holder_of(p);
  if (holder >= 0) return holder;
  const auto report = producers_->reports.find(p);
  return report == producers_->reports.end() ? -1 : report->second;
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
