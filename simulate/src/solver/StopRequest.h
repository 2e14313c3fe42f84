#pragma once
// A stop the user asked for (SIGTERM, SIGINT: a batch scheduler's notice, Ctrl-C), set by
// the checkpointer's signal handler and read between Newton iterations, so that a step of
// minutes on a large wall is abandoned within one iteration instead of finished: the run
// then stops at its last completed step (docs/simulate.md, "Checkpoint and resume").
#include <csignal>

namespace vesica::simulate {

// Async-signal-safe: records `signal` (0 clears the request).
void request_stop(int signal);
// The signal of the pending request, or 0.
int stop_signal();
inline bool stop_requested() {
  return stop_signal() != 0;
}

}  // namespace vesica::simulate
