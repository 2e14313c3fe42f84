#include "vesica/core/Log.h"

#include <spdlog/sinks/stdout_color_sinks.h>

namespace vesica {

std::shared_ptr<spdlog::logger> log() {
  static std::shared_ptr<spdlog::logger> logger = [] {
    auto l = spdlog::stderr_color_mt("vesica");
    l->set_pattern("%^%l%$: %v");
    l->set_level(spdlog::level::info);
    return l;
  }();
  return logger;
}

void configure_logging(bool quiet, bool verbose) {
  log()->set_level(quiet ? spdlog::level::warn
                         : (verbose ? spdlog::level::debug : spdlog::level::info));
}

}  // namespace vesica
