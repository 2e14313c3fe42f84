#pragma once
// Internal to vesica_pipelines: what `vesica run` writes on stderr. Log lines go out as
// they come. On a terminal, the running stage's own progress line (vesica::Progress:
// step, fraction, time left) is drawn in place under them, cut to the terminal's width,
// and cleared before the next log line. Elsewhere (stderr piped to a file or a CI log) each
// step of a stage gets one whole line when it starts, and another a minute apart while it
// lasts, so that a long run is seen to be alive and a log file holds only whole lines.
#include <chrono>
#include <string>

namespace vesica::pipelines::detail {

class RunnerTerminal {
 public:
  // `terminal`: stderr is a terminal; `progress`: progress is wanted (no --json).
  RunnerTerminal(bool terminal, bool progress) : terminal_(terminal), progress_(progress) {}
  ~RunnerTerminal() { clear(); }
  RunnerTerminal(const RunnerTerminal&) = delete;
  RunnerTerminal& operator=(const RunnerTerminal&) = delete;

  bool shows_progress() const { return progress_; }
  void line(const std::string& text);
  void progress(const std::string& text);
  void clear();

 private:
  void log_step(const std::string& text);

  bool terminal_;
  bool progress_;
  bool drawn_ = false;
  std::string logged_step_;
  std::chrono::steady_clock::time_point logged_at_;
};

}  // namespace vesica::pipelines::detail
