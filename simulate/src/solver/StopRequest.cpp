#include "solver/StopRequest.h"

#include <atomic>
#include <cstdlib>

namespace vesica::simulate {
namespace {

volatile std::sig_atomic_t g_stop_signal = 0;

}  // namespace

void request_stop(int signal) {
  g_stop_signal = signal;
}

int stop_signal() {
  return g_stop_signal;
}

void count_iteration() {
  static const long stop_after = [] {
    const char* k = std::getenv("VESICA_SIMULATE_STOP_AFTER_ITERATIONS");
    return k ? std::atol(k) : -1L;
  }();
  static std::atomic<long> iterations{0};
  if (++iterations == stop_after) std::raise(SIGTERM);
}

}  // namespace vesica::simulate
