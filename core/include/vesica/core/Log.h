#pragma once
// Logging goes through spdlog to stderr. Stages log with vesica::log()->info(...);
// --json raises the level to warnings so that stdout carries only the JSON.
#include <memory>

#include <spdlog/spdlog.h>

namespace vesica {
std::shared_ptr<spdlog::logger> log();
void configure_logging(bool quiet, bool verbose);
}  // namespace vesica
