#pragma once
// Progress of long work on a terminal: "[stage] step  42%  12.3 s elapsed, ~17 s left".
// Silent when stderr is not a terminal (unless VESICA_PROGRESS=1: `vesica run` sets it to
// draw a stage's progress on its own terminal) or when the tool runs with --json.
#include <chrono>
#include <string>

namespace vesica {

// Global switch, set once by the executable's main (--json makes everything quiet).
void set_quiet(bool quiet);
bool is_quiet();

class Progress {
 public:
  explicit Progress(std::string stage);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // fraction in [0, 1] of the whole stage; redraws at most ten times a second.
  void update(const std::string& step, double fraction);
  // Ends the line.
  void finish();

 private:
  std::string stage_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_draw_;
  bool enabled_;
  bool drawn_ = false;
};

}  // namespace vesica
