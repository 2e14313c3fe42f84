#include "vesica/pipelines/Staleness.h"

#include <algorithm>
#include <map>

#include "Joined.h"
#include "vesica/pipelines/StageCheckpoint.h"
#include "vesica/pipelines/StageFailure.h"
#include "vesica/pipelines/StageManifest.h"
#include "vesica/pipelines/StateFolder.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

using detail::joined;

bool is_option(const std::string& token) {
  return token.size() > 1 && token[0] == '-';
}

// Options of an invocation: --key -> value ("" for a bare flag), plus the positionals.
struct ParsedInvocation {
  std::map<std::string, std::string> options;
  std::vector<std::string> positional;
};

ParsedInvocation parse(const std::vector<std::string>& argv) {
  ParsedInvocation p;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    if (!is_option(argv[i])) {
      p.positional.push_back(argv[i]);
    } else if (i + 1 < argv.size() && !is_option(argv[i + 1])) {
      p.options[argv[i]] = argv[i + 1];
      ++i;
    } else {
      p.options[argv[i]] = "";
    }
  }
  return p;
}

std::string pipeline_key(const std::string& option) {
  std::string key = option.substr(option.find_first_not_of('-'));
  for (char& c : key)
    if (c == '-') c = '_';
  return key;
}

std::string shown(const std::string& value) {
  return value.empty() ? "on" : value;
}

std::vector<std::string> strings(const nlohmann::json& j) {
  std::vector<std::string> out;
  if (j.is_array())
    for (const auto& x : j)
      if (x.is_string()) out.push_back(x.get<std::string>());
  return out;
}

// The stage's reason to run other than its outputs: version, invocation, inputs ("" when
// they agree).
std::string own_reason(const Plan& plan, const PlannedStage& s, const StageManifest& m) {
  const std::string recorded_version = m.json.value("version", "");
  if (recorded_version != vesica::version())
    return "tool version changed (" + recorded_version + " -> " + vesica::version() + ")";
  // A resumed run's invocation ends in --resume, which the runner added: not a parameter.
  const std::vector<std::string> invocation =
      without_resume(strings(m.json.value("invocation", nlohmann::json())));
  if (invocation != s.argv) return describe_invocation_change(invocation, s.argv);
  for (const FileRecord& r : m.inputs) {
    const FileState what = compare_with_record(plan.in_workdir(r.path), r, m.written);
    if (what == FileState::Same) continue;
    std::string reason = "input " + r.path + " " + to_string(what);
    const long producer = plan.producer_of(r.path);
    if (producer >= 0) reason += " (upstream " + plan.stages[producer].id + ")";
    return reason;
  }
  return "";
}

// Outputs that differ from `records`; a state file (.vesica/...) that does is no edit
// of the user's and goes to `other` instead, as does a missing output.
void compare_outputs(const Plan& plan, const std::vector<FileRecord>& records,
                     fs::file_time_type written, std::vector<std::string>& edited,
                     std::string& other) {
  for (const FileRecord& r : records) {
    const FileState what = compare_with_record(plan.in_workdir(r.path), r, written);
    if (what == FileState::Same) continue;
    if (what == FileState::Changed && !state::is_state_path(r.path))
      edited.push_back(r.path);
    else if (other.empty())
      other = "output " + r.path + (what == FileState::Missing ? " is missing" : " changed");
  }
}

StageStatus edited_status(const PlannedStage& s, const std::vector<std::string>& edited,
                          const std::string& other) {
  StageStatus st{Freshness::Edited, joined(edited), edited};
  if (!other.empty())
    st.reason += "; also " + other + " (kept anyway; `vesica reset` reruns " + s.stage + ")";
  return st;
}

// An interrupted stage that left a checkpoint it can resume from says so; else the
// failure record's description.
std::string failure_reason(const Plan& plan, const PlannedStage& s, const StageFailure& failure) {
  const bool interrupted =
      failure.state == StageFailure::State::Interrupted ||
      (failure.state == StageFailure::State::Running && !failure.runner_alive());
  if (interrupted)
    if (const auto c = resumable_checkpoint(plan, s)) return checkpoint_status(*c);
  return failure.describe();
}

// No manifest: never run, or its last run did not finish. After a failure the runner
// recorded the outputs as the stage left them, so a file saved there since (a label map
// painted by hand after the segmentation failed) is an edit like any other. A run that was
// killed outright recorded nothing reliable, and the stage just runs again.
StageStatus without_manifest(const Plan& plan, const PlannedStage& s) {
  const auto failure = read_stage_failure(plan, s.id);
  if (!failure) return {Freshness::Missing, "not run yet (no manifest " + s.manifest + ")", {}};
  if (failure->state == StageFailure::State::Running)
    return {failure->runner_alive() ? Freshness::Running : Freshness::Failed,
            failure_reason(plan, s, *failure),
            {}};
  std::vector<std::string> edited;
  std::string other;
  compare_outputs(plan, failure->outputs_before, fs::file_time_type::min(), edited, other);
  std::error_code ec;
  if (!recorded(failure->outputs_before, s.output) && fs::exists(plan.in_workdir(s.output), ec))
    edited.push_back(s.output);
  if (!edited.empty()) return edited_status(s, edited, failure_reason(plan, s, *failure));
  return {Freshness::Failed, failure_reason(plan, s, *failure), {}};
}

}  // namespace

const char* to_string(Freshness f) {
  switch (f) {
    case Freshness::Fresh:
      return "fresh";
    case Freshness::Stale:
      return "stale";
    case Freshness::Missing:
      return "missing";
    case Freshness::Edited:
      return "edited";
    case Freshness::Failed:
      return "failed";
    case Freshness::Running:
      return "running";
  }
  return "stale";
}

bool StageStatus::will_run() const {
  return state != Freshness::Fresh && state != Freshness::Edited;
}

std::string StageStatus::line() const {
  switch (state) {
    case Freshness::Fresh:
      return "fresh";
    case Freshness::Edited:
      return "edited (kept): " + reason;
    case Freshness::Failed:
    case Freshness::Running:
      return reason;
    case Freshness::Stale:
    case Freshness::Missing:
      break;
  }
  return std::string(to_string(state)) + ": " + reason;
}

std::string describe_invocation_change(const std::vector<std::string>& before,
                                       const std::vector<std::string>& after) {
  const ParsedInvocation a = parse(before), b = parse(after);
  for (const auto& [option, value] : b.options) {
    auto it = a.options.find(option);
    if (it == a.options.end())
      return "parameter " + pipeline_key(option) + " added (" + shown(value) + ")";
    if (it->second != value)
      return "parameter " + pipeline_key(option) + " changed (" + shown(it->second) + " -> " +
             shown(value) + ")";
  }
  for (const auto& [option, value] : a.options)
    if (!b.options.count(option)) return "parameter " + pipeline_key(option) + " removed";
  if (a.positional != b.positional) return "inputs on the command line changed";
  return "command line changed (argument order)";
}

StageStatus assess_stage(const Plan& plan, std::size_t index) {
  const PlannedStage& s = plan.stages[index];
  const auto m = read_stage_manifest(plan.in_workdir(s.manifest));
  if (!m) return without_manifest(plan, s);
  if (!m->readable()) return {Freshness::Stale, "manifest " + s.manifest + " is unreadable", {}};
  const std::string own = own_reason(plan, s, *m);
  std::vector<std::string> edited;
  std::string output_problem;
  compare_outputs(plan, m->outputs, m->written, edited, output_problem);
  if (!edited.empty()) return edited_status(s, edited, own.empty() ? output_problem : own);
  if (!own.empty()) return {Freshness::Stale, own, {}};
  if (!output_problem.empty()) return {Freshness::Stale, output_problem, {}};
  return {Freshness::Fresh, "", {}};
}

std::vector<StageStatus> assess(const Plan& plan) {
  std::vector<StageStatus> out;
  out.reserve(plan.stages.size());
  for (std::size_t i = 0; i < plan.stages.size(); ++i) {
    StageStatus st = assess_stage(plan, i);
    // An edited stage keeps its files whatever happens above it, so it neither inherits
    // nor passes on an upstream change; its readers check their own inputs.
    if (st.state == Freshness::Fresh)
      for (std::size_t d : plan.stages[i].deps)
        if (out[d].will_run()) {
          st = {Freshness::Stale,
                "upstream " + plan.stages[d].id + " is " + to_string(out[d].state),
                {}};
          break;
        }
    out.push_back(st);
  }
  return out;
}

}  // namespace vesica::pipelines
