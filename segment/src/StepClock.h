#pragma once
// Seconds per step into a JSON object of the diagnostics, to see where the time goes.
#include <chrono>
#include <string>

#include <nlohmann/json.hpp>

namespace vesica::segment {

class StepClock {
 public:
  explicit StepClock(nlohmann::json& out) : out_(out) {}
  void lap(const std::string& step) {
    const auto now = std::chrono::steady_clock::now();
    out_[step] = std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  nlohmann::json& out_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace vesica::segment
