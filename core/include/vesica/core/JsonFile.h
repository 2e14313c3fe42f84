#pragma once
// vesica's own JSON files read back (manifests, failure records, stage reports, a
// simulation's summary): a regular file of bounded size (InputFile.h), parsed without
// exceptions. What it holds is still the caller's to check, field by field.
#include <cstdint>
#include <filesystem>
#include <optional>

#include <nlohmann/json.hpp>

#include "vesica/core/InputFile.h"

namespace vesica {

// Nothing when `path` does not exist; else its JSON, discarded (is_discarded()) when it is
// not JSON or nests more than 64 levels (nlohmann's dump and comparison recurse per level). Throws
// vesica::Error naming the file when it is not a regular file or is larger than `max_bytes`.
std::optional<nlohmann::json> read_json_file(const std::filesystem::path& path,
                                             std::uintmax_t max_bytes = kMaxStateFileBytes);

}  // namespace vesica
