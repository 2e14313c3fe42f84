#include "solver/StopRequest.h"

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

}  // namespace vesica::simulate
