#include "vesica/pipelines/CapacityStress.h"

#include <nlohmann/json.hpp>

#include "vesica/core/Error.h"
#include "vesica/pipelines/ChildProcess.h"

namespace vesica::pipelines {

nlohmann::json capacity_stress(const std::filesystem::path& compare_executable,
                               const std::filesystem::path& simulation, std::string& why) {
  why.clear();
  if (!std::filesystem::exists(simulation / "series.pvd")) return nullptr;
  std::vector<std::string> lines;
  int status = -1;
  try {
    ChildProcess child(
        compare_executable,
        {"--wall-stress-at-capacity", std::filesystem::absolute(simulation).string()}, simulation);
    ChildOutput out;
    while (child.read(out)) {
    }
    lines = std::move(out.lines);
    status = child.wait();
  } catch (const Error& e) {
    why = e.what();
    return nullptr;
  }
  // The JSON is the last line; warnings, if any, come before it.
  nlohmann::json j =
      lines.empty() ? nlohmann::json() : nlohmann::json::parse(lines.back(), nullptr, false);
  if (status != 0 || j.is_discarded() || !j.is_object()) {
    why = compare_executable.filename().string() + " --wall-stress-at-capacity failed" +
          (lines.empty() ? "" : ": " + lines.back());
    return nullptr;
  }
  return j;
}

}  // namespace vesica::pipelines
