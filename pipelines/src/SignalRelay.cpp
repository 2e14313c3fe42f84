#include "vesica/pipelines/SignalRelay.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>

#include "vesica/core/Error.h"

namespace vesica::pipelines {
namespace {

constexpr int kRelayed[] = {SIGINT, SIGTERM, SIGHUP};

// Written by the handler: only async-signal-safe state.
int g_pipe[2] = {-1, -1};
volatile std::sig_atomic_t g_first = 0;
struct sigaction g_previous[3];

void on_signal(int signal) {
  if (g_first == 0) g_first = signal;
  const unsigned char byte = static_cast<unsigned char>(signal);
  const int saved = errno;
  [[maybe_unused]] const ssize_t n = ::write(g_pipe[1], &byte, 1);
  errno = saved;
}

}  // namespace

SignalRelay::SignalRelay() {
  if (::pipe2(g_pipe, O_CLOEXEC | O_NONBLOCK) != 0) fail("vesica", "cannot create a pipe");
  g_first = 0;
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  for (int k = 0; k < 3; ++k) ::sigaction(kRelayed[k], &action, &g_previous[k]);
}

SignalRelay::~SignalRelay() {
  for (int k = 0; k < 3; ++k) ::sigaction(kRelayed[k], &g_previous[k], nullptr);
  ::close(g_pipe[0]);
  ::close(g_pipe[1]);
  g_pipe[0] = g_pipe[1] = -1;
}

int SignalRelay::wake_fd() const {
  return g_pipe[0];
}

int SignalRelay::take() {
  unsigned char bytes[64];
  int last = 0;
  for (ssize_t n; (n = ::read(g_pipe[0], bytes, sizeof bytes)) > 0;) last = bytes[n - 1];
  return last;
}

int SignalRelay::first() const {
  return g_first;
}

const char* signal_name(int signal) {
  switch (signal) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    case SIGKILL:
      return "SIGKILL";
    default:
      return "a signal";
  }
}

}  // namespace vesica::pipelines
