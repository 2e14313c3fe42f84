#pragma once
// Internal to vesica_pipelines: what `vesica run` writes on stderr. Log lines go out as
// they come. On a terminal, the running stage's own progress line (vesica::Progress:
// step, fraction, time left) is drawn in place under them, cut to the terminal's width,
// and cleared before the next log line; elsewhere progress lines are dropped, so that a
// log file holds only whole lines.
#include <string>

namespace vesica::pipelines::detail {

class RunnerTerminal {
 public:
  // `terminal`: stderr is a terminal and progress is wanted (no --json).
  explicit RunnerTerminal(bool terminal) : terminal_(terminal) {}
  ~RunnerTerminal() { clear(); }
  RunnerTerminal(const RunnerTerminal&) = delete;
  RunnerTerminal& operator=(const RunnerTerminal&) = delete;

  bool shows_progress() const { return terminal_; }
  void line(const std::string& text);
  void progress(const std::string& text);
  void clear();

 private:
  bool terminal_;
  bool drawn_ = false;
};

}  // namespace vesica::pipelines::detail
