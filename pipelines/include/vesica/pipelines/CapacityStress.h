#pragma once
// The wall stress at capacity of one simulation folder for the study table: what
// `vesica-compare --wall-stress-at-capacity DIR` prints (the capacity frame's 95th
// percentile, maximum and where, and its outline seen from the front). The runner asks the
// compare executable instead of reading the .vtu itself, so that `vesica` does not load the
// imaging libraries at every start.
#include <filesystem>
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace vesica::pipelines {

// Null when the folder has no series.pvd, or when the tool fails (then `why` says so).
nlohmann::json capacity_stress(const std::filesystem::path& compare_executable,
                               const std::filesystem::path& simulation, std::string& why);

}  // namespace vesica::pipelines
