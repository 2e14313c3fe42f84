#include "vesica/pipelines/Runner.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>

#include <nlohmann/json.hpp>

#include "Joined.h"
#include "vesica/core/Error.h"
#include "vesica/core/UidScrub.h"
#include "vesica/pipelines/ChildProcess.h"
#include "vesica/pipelines/EditBackup.h"
#include "vesica/pipelines/MeshEditFollow.h"
#include "vesica/pipelines/SignalRelay.h"
#include "vesica/pipelines/StageCheckpoint.h"
#include "vesica/pipelines/StageFailure.h"
#include "vesica/pipelines/StageManifest.h"
#include "vesica/pipelines/StateFolder.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

using detail::joined;

using Clock = std::chrono::steady_clock;

std::vector<bool> matching(const Plan& plan, const std::vector<std::string>& names) {
  std::vector<bool> hit(plan.stages.size(), false);
  for (const auto& name : names)
    for (std::size_t i : plan.named(name)) hit[i] = true;
  return hit;
}

// "[vesica-mesh] tetrahedra 40%" -> "tetrahedra 40%": the runner puts the stage's id there.
std::string without_tool_prefix(const std::string& progress) {
  if (progress.empty() || progress[0] != '[') return progress;
  const auto end = progress.find("] ");
  return end == std::string::npos ? progress : progress.substr(end + 2);
}

// The files a stage's run may leave at its outputs' places: the planned output, the files
// it writes beside it and every output its manifest recorded, not vesica's own files.
std::vector<std::string> output_places(const Plan& plan, const PlannedStage& s) {
  std::vector<std::string> paths = {s.output};
  paths.insert(paths.end(), s.side_outputs.begin(), s.side_outputs.end());
  if (const auto m = read_stage_manifest(plan.in_workdir(s.manifest)); m && m->readable())
    for (const auto& r : m->outputs)
      if (!state::is_state_path(r.path) && r.path != s.report &&
          std::find(paths.begin(), paths.end(), r.path) == paths.end())
        paths.push_back(r.path);
  return paths;
}

// Records of what is at those places now (for the failure record).
std::vector<FileRecord> records_of(const Plan& plan, const std::vector<std::string>& paths) {
  std::vector<FileRecord> out;
  for (const auto& path : paths) {
    std::error_code ec;
    if (!fs::exists(plan.in_workdir(path), ec)) continue;
    try {
      FileRecord r = record_file(plan.in_workdir(path));
      r.path = path;
      out.push_back(r);
    } catch (const std::exception&) {
      // Unreadable: without a record the next run saves it before replacing it.
    }
  }
  return out;
}

struct Running {
  std::size_t index;
  std::unique_ptr<ChildProcess> process;
  Clock::time_point start;
};

class Execution {
 public:
  Execution(const Plan& plan, const RunOptions& options, const std::vector<StageStatus>& status,
            const std::vector<bool>& selected)
      : plan_(plan),
        options_(options),
        selected_(selected),
        done_(plan.stages.size(), false),
        lines_(plan.stages.size()),
        places_(plan.stages.size()) {
    for (std::size_t i = 0; i < plan.stages.size(); ++i) {
      StageOutcome o;
      o.id = plan.stages[i].id;
      o.reason = status[i].reason;
      if (selected[i])
        o.action = "blocked";
      else if (status[i].state == Freshness::Edited)
        o.action = "kept", o.kept = status[i].edited;
      else
        o.action = status[i].state == Freshness::Fresh ? "fresh" : "skipped";
      if (selected[i] && status[i].state == Freshness::Edited)
        o.reason = "discarding your edit of " + joined(status[i].edited);
      if (selected[i] && o.reason.empty()) o.reason = "forced";
      result_.stages.push_back(o);
      if (selected[i]) ++total_;
    }
  }

  RunResult run() {
    state::require_state_folder(plan_.workdir);
    for (std::size_t i = 0; i < plan_.stages.size(); ++i)
      if (result_.stages[i].action == "kept")
        follow_kept_mesh_edit(plan_, i, [&](const std::string& line) { say(line); });
    SignalRelay relay;
    while (true) {
      if (!relay_signal_ && (result_.ok || options_.keep_going)) launch_ready();
      if (running_.empty()) break;
      wait_for_output(relay);
    }
    if (relay_signal_) {
      result_.ok = false;
      result_.interrupted_by = relay_signal_;
    }
    return result_;
  }

 private:
  void say(const std::string& line) {
    if (options_.progress) options_.progress(line);
  }

  bool ready(std::size_t i) const {
    if (!selected_[i] || done_[i] || started(i)) return false;
    for (std::size_t d : plan_.stages[i].deps)
      if (selected_[d] && (!done_[d] || result_.stages[d].action != "ran")) return false;
    return true;
  }

  bool started(std::size_t i) const {
    for (const auto& r : running_)
      if (r.index == i) return true;
    return false;
  }

  void launch_ready() {
    for (std::size_t i = 0; i < plan_.stages.size(); ++i) {
      if (static_cast<int>(running_.size()) >= std::max(1, options_.jobs)) return;
      if (!result_.ok && !options_.keep_going) return;  // a stage could not even start
      if (!ready(i)) continue;
      launch(i);
    }
  }

  void launch(std::size_t i) {
    const PlannedStage& s = plan_.stages[i];
    StageOutcome& o = result_.stages[i];
    ++launched_;
    say("vesica: [" + std::to_string(launched_) + "/" + std::to_string(total_) + "] " + s.id +
        ": " + o.reason);
    try {
      const bool was_interrupted = interrupted_before(s);
      const Backup backup = back_up_outputs(plan_, i);
      if (!backup.files.empty()) {
        o.backed_up = backup.files;
        o.backup_folder = backup.folder;
        say("vesica: " + s.id + ": saved " + joined(backup.files) + " to " +
            (plan_.workdir / backup.folder).string() + " before replacing");
      }
      places_[i] = output_places(plan_, s);
      // Marks the stage as running (the runner's PID), so that a runner killed outright
      // leaves it "interrupted"; without its manifest it stays stale for the next run.
      StageFailure running;
      running.state = StageFailure::State::Running;
      running.pid = ::getpid();
      write_stage_failure(plan_, s.id, running);
      std::error_code ec;
      fs::remove(plan_.in_workdir(s.manifest), ec);
      running_.push_back({i,
                          std::make_unique<ChildProcess>(
                              s.executable, arguments(s, was_interrupted), plan_.workdir),
                          Clock::now()});
    } catch (const Error& e) {
      finish(i, 127, 0.0, {e.what()});
    }
  }

  // Whether the stage's last run was interrupted (by a signal, or its runner killed).
  bool interrupted_before(const PlannedStage& s) const {
    const auto failure = read_stage_failure(plan_, s.id);
    return failure &&
           (failure->state == StageFailure::State::Interrupted ||
            (failure->state == StageFailure::State::Running && !failure->runner_alive()));
  }

  // The stage's arguments: with --resume for an interrupted stage that can continue from
  // a valid checkpoint of its present inputs and arguments.
  std::vector<std::string> arguments(const PlannedStage& s, bool was_interrupted) {
    std::vector<std::string> argv = s.argv;
    if (!was_interrupted) return argv;
    if (const auto c = resumable_checkpoint(plan_, s)) {
      char t[32];
      std::snprintf(t, sizeof t, "%.6g", c->time_s);
      say("vesica: resuming " + s.id + " from its checkpoint at t = " + t + " s");
      argv.push_back("--resume");
    }
    return argv;
  }

  void wait_for_output(SignalRelay& relay) {
    std::vector<pollfd> fds;
    for (const auto& r : running_) fds.push_back({r.process->output_fd(), POLLIN, 0});
    fds.push_back({relay.wake_fd(), POLLIN, 0});
    if (::poll(fds.data(), fds.size(), -1) < 0) return;
    if (fds.back().revents & POLLIN) pass_on(relay.take());
    for (std::size_t k = running_.size(); k-- > 0;) {
      if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      Running& r = running_[k];
      ChildOutput output;
      const bool open = r.process->read(output);
      for (const auto& line : output.lines) forward(r.index, line);
      if (output.progress && !options_.capture && options_.progress_line)
        options_.progress_line("  [" + plan_.stages[r.index].id + "] " +
                               without_tool_prefix(*output.progress));
      if (open) continue;
      const int code = r.process->wait();
      const double seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
      const std::size_t index = r.index;
      running_.erase(running_.begin() + static_cast<long>(k));
      finish(index, code, seconds, {});
    }
  }

  // A signal for the runner goes to every running stage's process group; the runner then
  // starts nothing more and waits for them (they write atomically, so they leave their
  // earlier outputs intact).
  void pass_on(int signal) {
    if (signal == 0) return;
    if (!relay_signal_) {
      relay_signal_ = signal;
      std::vector<std::string> ids;
      for (const auto& r : running_) ids.push_back(plan_.stages[r.index].id);
      say(std::string("vesica: ") + signal_name(signal) + ": stopping " +
          (ids.empty() ? std::string("nothing (no stage running)") : joined(ids)) +
          ", waiting for it to end");
    }
    for (const auto& r : running_) r.process->signal_group(signal);
  }

  // Every line a stage prints reaches the terminal, the run's JSON and the failure record
  // through here: without DICOM UIDs (a slice's file name may be one).
  void forward(std::size_t i, const std::string& raw) {
    const std::string line = without_uids(raw);
    StageOutcome& o = result_.stages[i];
    lines_[i].push_back(line);
    if (options_.capture)
      o.log.push_back(line);
    else
      say("  [" + o.id + "] " + line);
  }

  void finish(std::size_t i, int code, double seconds, const std::vector<std::string>& extra) {
    StageOutcome& o = result_.stages[i];
    const PlannedStage& s = plan_.stages[i];
    done_[i] = true;
    o.seconds = seconds;
    o.exit_code = code;
    for (const auto& line : extra) forward(i, line);
    o.last_line = error_line(lines_[i]);
    if (code == 0) {
      o.action = "ran";
      clear_stage_failure(plan_, s.id);
      say("vesica: " + o.id + " done in " + format_seconds(seconds));
      if (!fs::exists(plan_.in_workdir(s.manifest)))
        say("vesica: warning: " + o.id + " wrote no manifest " + s.manifest +
            "; it will run again next time");
      return;
    }
    // A stage may write its manifest before failing (vesica-simulate keeps the results up
    // to a stalled step). Removing it keeps the rule that a failed stage runs again next
    // time, as Snakemake deletes a failed job's outputs.
    std::error_code ec;
    fs::remove(plan_.in_workdir(s.manifest), ec);
    StageFailure failure;
    failure.pid = ::getpid();
    failure.exit_code = code;
    failure.outputs_before = records_of(plan_, places_[i]);
    if (relay_signal_) {
      o.action = "interrupted";
      failure.state = StageFailure::State::Interrupted;
      failure.error = signal_name(relay_signal_);
    } else {
      o.action = "failed";
      failure.error = o.last_line;
    }
    try {
      write_stage_failure(plan_, s.id, failure);
    } catch (const Error& e) {
      say(std::string("vesica: warning: ") + e.what());
    }
    if (result_.ok && !relay_signal_) {
      result_.ok = false;
      result_.failed_stage = o.id;
      result_.failure_line = o.last_line;
    }
  }

  static std::string format_seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.2f s", s);
    return buf;
  }

  const Plan& plan_;
  const RunOptions& options_;
  std::vector<bool> selected_;
  std::vector<bool> done_;
  std::vector<std::vector<std::string>> lines_;   // every line each stage printed
  std::vector<std::vector<std::string>> places_;  // each started stage's output places
  std::vector<Running> running_;
  RunResult result_;
  int total_ = 0;
  int launched_ = 0;
  int relay_signal_ = 0;
};

}  // namespace

std::vector<bool> select_stages(const Plan& plan, const std::vector<StageStatus>& status,
                                const RunOptions& options) {
  const std::size_t n = plan.stages.size();
  const std::vector<bool> only = matching(plan, options.only);
  const std::vector<bool> from = matching(plan, options.from);
  const std::vector<bool> discard = matching(plan, options.discard_edits);
  std::vector<bool> forced(n, options.force);
  for (std::size_t i = 0; i < n; ++i)
    if (from[i] || discard[i]) {
      forced[i] = true;
      for (std::size_t d : plan.downstream_of(i)) forced[d] = true;
    }
  std::vector<bool> selected(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    // An edit is the user's: neither --force nor --from replaces it, only --discard-edits.
    if (status[i].state == Freshness::Edited && !discard[i]) continue;
    selected[i] = forced[i] || status[i].will_run();
    for (std::size_t d : plan.stages[i].deps) selected[i] = selected[i] || selected[d];
  }
  if (!options.only.empty())
    for (std::size_t i = 0; i < n; ++i) selected[i] = selected[i] && only[i];
  return selected;
}

std::vector<std::string> RunResult::ran() const {
  std::vector<std::string> ids;
  for (const auto& s : stages)
    if (s.action == "ran") ids.push_back(s.id);
  return ids;
}

std::vector<std::string> RunResult::kept_files() const {
  std::vector<std::string> files;
  for (const auto& s : stages)
    for (const auto& f : s.kept) files.push_back(f + " (" + s.id + ")");
  return files;
}

nlohmann::json RunResult::to_json() const {
  nlohmann::json stages_json = nlohmann::json::array();
  for (const auto& s : stages) {
    nlohmann::json j = {{"id", s.id},           {"action", s.action},       {"reason", s.reason},
                        {"seconds", s.seconds}, {"exit_code", s.exit_code}, {"log", s.log}};
    if (!s.kept.empty()) j["kept"] = s.kept;
    if (!s.backed_up.empty()) j["backed_up"] = s.backed_up, j["backup_folder"] = s.backup_folder;
    stages_json.push_back(j);
  }
  nlohmann::json j = {{"ok", ok}, {"ran", ran()}, {"kept", kept_files()}, {"stages", stages_json}};
  if (!failed_stage.empty()) j["failed_stage"] = failed_stage, j["failure"] = failure_line;
  if (interrupted_by) j["interrupted_by"] = signal_name(interrupted_by);
  return j;
}

RunResult run_plan(const Plan& plan, const RunOptions& options) {
  const std::vector<StageStatus> status = assess(plan);
  const std::vector<bool> selected = select_stages(plan, status, options);
  return Execution(plan, options, status, selected).run();
}

}  // namespace vesica::pipelines
