#pragma once
// The fuzz label's checkpoint reader, in a file of its own: it needs Eigen's sparse
// module, which cannot share a translation unit with ITK's headers (ITK brings its own,
// older Eigen under the same include guards).
#include <filesystem>
#include <vector>

namespace vesica::fuzz {

// A checkpoint with every kind of field vesica-simulate writes.
std::vector<std::filesystem::path> checkpoint_seeds(const std::filesystem::path& dir);

// The checkpoint read back field by field, as a resumed run reads its state.
void read_checkpoint_fields(const std::filesystem::path& input);

}  // namespace vesica::fuzz
