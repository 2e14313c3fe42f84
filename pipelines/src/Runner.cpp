#include "vesica/pipelines/Runner.h"

#include <poll.h>

#include <chrono>
#include <map>
#include <memory>

#include "vesica/core/Error.h"
#include "vesica/pipelines/ChildProcess.h"
#include "vesica/core/Suggest.h"

namespace fs = std::filesystem;

namespace vesica::pipelines {
namespace {

using Clock = std::chrono::steady_clock;

bool matches(const PlannedStage& s, const std::string& name) {
  return s.id == name || s.stage == name;
}

std::vector<bool> matching(const Plan& plan, const std::vector<std::string>& names) {
  std::vector<bool> hit(plan.stages.size(), false);
  std::vector<std::string> ids;
  for (const auto& s : plan.stages) ids.push_back(s.id);
  for (const auto& name : names) {
    bool any = false;
    for (std::size_t i = 0; i < plan.stages.size(); ++i)
      if (matches(plan.stages[i], name)) hit[i] = any = true;
    if (!any) usage_error("no stage named '" + name + "'" + did_you_mean(name, ids));
  }
  return hit;
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
      : plan_(plan), options_(options), selected_(selected), done_(plan.stages.size(), false) {
    for (std::size_t i = 0; i < plan.stages.size(); ++i) {
      StageOutcome o;
      o.id = plan.stages[i].id;
      o.reason = status[i].reason;
      o.action =
          selected[i] ? "blocked" : (status[i].state == Freshness::Fresh ? "fresh" : "skipped");
      if (selected[i] && o.reason.empty()) o.reason = "forced";
      result_.stages.push_back(o);
      if (selected[i]) ++total_;
    }
  }

  RunResult run() {
    fs::create_directories(plan_.workdir);
    while (true) {
      if (result_.ok || options_.keep_going) launch_ready();
      if (running_.empty()) break;
      wait_for_output();
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
      const PlannedStage& s = plan_.stages[i];
      ++launched_;
      say("vesica: [" + std::to_string(launched_) + "/" + std::to_string(total_) + "] " + s.id +
          ": " + result_.stages[i].reason);
      // Without its manifest an interrupted or failed stage stays stale for the next run.
      std::error_code ec;
      fs::remove(plan_.in_workdir(s.manifest), ec);
      try {
        running_.push_back(
            {i, std::make_unique<ChildProcess>(s.executable, s.argv, plan_.workdir), Clock::now()});
      } catch (const Error& e) {
        finish(i, 127, 0.0, {e.what()});
      }
    }
  }

  void wait_for_output() {
    std::vector<pollfd> fds;
    for (const auto& r : running_) fds.push_back({r.process->output_fd(), POLLIN, 0});
    if (::poll(fds.data(), fds.size(), -1) < 0) return;
    for (std::size_t k = fds.size(); k-- > 0;) {
      if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      Running& r = running_[k];
      std::vector<std::string> lines;
      const bool open = r.process->read_lines(lines);
      for (const auto& line : lines) forward(r.index, line);
      if (open) continue;
      const int code = r.process->wait();
      const double seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
      const std::size_t index = r.index;
      running_.erase(running_.begin() + static_cast<long>(k));
      finish(index, code, seconds, {});
    }
  }

  void forward(std::size_t i, const std::string& line) {
    StageOutcome& o = result_.stages[i];
    if (!line.empty()) last_line_[plan_.stages[i].id] = line;
    if (options_.capture)
      o.log.push_back(line);
    else
      say("  [" + o.id + "] " + line);
  }

  void finish(std::size_t i, int code, double seconds, const std::vector<std::string>& extra) {
    StageOutcome& o = result_.stages[i];
    done_[i] = true;
    o.seconds = seconds;
    o.exit_code = code;
    for (const auto& line : extra) forward(i, line);
    o.last_line = last_line_[o.id];
    if (code == 0) {
      o.action = "ran";
      say("vesica: " + o.id + " done in " + format_seconds(seconds));
      if (!fs::exists(plan_.in_workdir(plan_.stages[i].manifest)))
        say("vesica: warning: " + o.id + " wrote no manifest " + plan_.stages[i].manifest +
            "; it will run again next time");
      return;
    }
    o.action = "failed";
    // A stage may write its manifest before failing (vesica-simulate keeps the results up
    // to a stalled step). Removing it keeps the rule that a failed stage is missing next
    // time, as Snakemake deletes a failed job's outputs.
    std::error_code ec;
    fs::remove(plan_.in_workdir(plan_.stages[i].manifest), ec);
    if (result_.ok) {
      result_.ok = false;
      result_.failed_stage = o.id;
      result_.failure_line = last_line_[o.id];
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
  std::vector<Running> running_;
  std::map<std::string, std::string> last_line_;
  RunResult result_;
  int total_ = 0;
  int launched_ = 0;
};

}  // namespace

std::vector<bool> select_stages(const Plan& plan, const std::vector<StageStatus>& status,
                                const RunOptions& options) {
  const std::size_t n = plan.stages.size();
  const std::vector<bool> only = matching(plan, options.only);
  const std::vector<bool> from = matching(plan, options.from);
  std::vector<bool> forced(n, options.force);
  for (std::size_t i = 0; i < n; ++i)
    if (from[i]) {
      forced[i] = true;
      for (std::size_t d : plan.downstream_of(i)) forced[d] = true;
    }
  std::vector<bool> selected(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    selected[i] = forced[i] || status[i].state != Freshness::Fresh;
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

nlohmann::json RunResult::to_json() const {
  nlohmann::json stages_json = nlohmann::json::array();
  for (const auto& s : stages)
    stages_json.push_back({{"id", s.id},
                           {"action", s.action},
                           {"reason", s.reason},
                           {"seconds", s.seconds},
                           {"exit_code", s.exit_code},
                           {"log", s.log}});
  nlohmann::json j = {{"ok", ok}, {"ran", ran()}, {"stages", stages_json}};
  if (!ok) j["failed_stage"] = failed_stage, j["failure"] = failure_line;
  return j;
}

RunResult run_plan(const Plan& plan, const RunOptions& options) {
  const std::vector<StageStatus> status = assess(plan);
  const std::vector<bool> selected = select_stages(plan, status, options);
  return Execution(plan, options, status, selected).run();
}

}  // namespace vesica::pipelines
