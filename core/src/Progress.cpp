#include "vesica/core/Progress.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace vesica {
namespace {
bool g_quiet = false;

// On a terminal; or when `vesica run` asks for it (VESICA_PROGRESS=1): the stage's stderr
// is then the runner's pipe, and the runner draws the line on its own terminal.
bool progress_wanted() {
  const char* relayed = std::getenv("VESICA_PROGRESS");
  return ::isatty(STDERR_FILENO) || (relayed && std::string(relayed) == "1");
}
}  // namespace

void set_quiet(bool quiet) {
  g_quiet = quiet;
}
bool is_quiet() {
  return g_quiet;
}

Progress::Progress(std::string stage)
    : stage_(std::move(stage)),
      start_(std::chrono::steady_clock::now()),
      enabled_(!g_quiet && progress_wanted()) {}

Progress::~Progress() {
  finish();
}

void Progress::update(const std::string& step, double fraction) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (drawn_ && now - last_draw_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
  last_draw_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  char left[64] = "";
  if (fraction > 0.02 && fraction < 1.0)
    std::snprintf(left, sizeof left, ", ~%.0f s left", elapsed * (1.0 - fraction) / fraction);
  std::fprintf(stderr, "\r\033[K[%s] %s %3.0f%%  %.1f s elapsed%s", stage_.c_str(), step.c_str(),
               100.0 * fraction, elapsed, left);
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (enabled_ && drawn_) std::fprintf(stderr, "\n");
  drawn_ = false;
}

}  // namespace vesica
