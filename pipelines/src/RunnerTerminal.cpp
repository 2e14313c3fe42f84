#include "RunnerTerminal.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>

namespace vesica::pipelines::detail {
namespace {

// A line longer than the terminal would wrap, and '\r' would then redraw only its end.
std::size_t terminal_width() {
  winsize size{};
  if (::ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 1) return size.ws_col - 1;
  return 79;
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

void RunnerTerminal::progress(const std::string& text) {
  if (!terminal_) return;
  std::fprintf(stderr, "\r\033[K%s", text.substr(0, terminal_width()).c_str());
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace vesica::pipelines::detail
