#pragma once
// While a SignalRelay lives, SIGINT, SIGTERM and SIGHUP no longer end the runner: each is
// noted and wakes the runner's poll() through a pipe, so that the runner can pass it on to
// its stages' process groups, wait for them to end and say what was interrupted. The
// previous handlers come back when it goes. One at a time per process.
namespace vesica::pipelines {

class SignalRelay {
 public:
  SignalRelay();
  ~SignalRelay();
  SignalRelay(const SignalRelay&) = delete;
  SignalRelay& operator=(const SignalRelay&) = delete;

  // Readable when a signal arrived.
  int wake_fd() const;
  // The last signal caught since the previous call, or 0. Drains the pipe.
  int take();
  // The first signal caught while this relay lived, or 0.
  int first() const;
};

// "SIGINT", "SIGTERM", ... for messages.
const char* signal_name(int signal);

}  // namespace vesica::pipelines
