#include "RunnerTerminal.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>

namespace vesica::pipelines::detail {
namespace {

// A line longer than the terminal would wrap, and '\r' would then redraw only its end.
std::size_t terminal_width() {
  winsize size{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 1) return size.ws_col - 1;
  return 79;
}

// "  [simulate] [vesica-simulate] filling 42%  12.3 s elapsed": the text before the
// percentage, which names the stage and its step.
std::string step_of(const std::string& progress) {
  const auto percent = progress.find('%');
  if (percent == std::string::npos) return progress;
  auto end = percent;
  while (end > 0 && (std::isdigit(static_cast<unsigned char>(progress[end - 1])) ||
                     progress[end - 1] == ' ' || progress[end - 1] == '.'))
    --end;
  return progress.substr(0, end);
}

}  // namespace

void RunnerTerminal::clear() {
  if (!drawn_) return;
  std::fputs("\r\033[K", stderr);
  std::fflush(stderr);
  drawn_ = false;
}

void RunnerTerminal::line(const std::string& text) {
  clear();
  std::fprintf(stderr, "%s\n", text.c_str());
}

void RunnerTerminal::log_step(const std::string& text) {
  const auto now = std::chrono::steady_clock::now();
  const std::string step = step_of(text);
  if (step == logged_step_ && now - logged_at_ < std::chrono::minutes(1)) return;
  logged_step_ = step;
  logged_at_ = now;
  std::fprintf(stderr, "%s\n", text.c_str());
}

void RunnerTerminal::progress(const std::string& text) {
  if (!progress_) return;
  if (!terminal_) return log_step(text);
  std::fprintf(stderr, "\r\033[K%s", text.substr(0, terminal_width()).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace vesica::pipelines::detail
