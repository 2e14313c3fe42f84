#pragma once
// Outputs are written under a temporary name in the destination folder and renamed
// into place only when complete, so that a crash, a bad input or a full disk never
// leaves a half-written file where a finished one was.
#include <filesystem>
#include <functional>
#include <string>

namespace vesica {

// A temporary path beside `target` that keeps its full extension (".nii.gz", ".vtp"),
// because ITK and VTK choose the file format from the name.
std::filesystem::path temporary_sibling(const std::filesystem::path& target);

// Calls write(tmp) with a temporary path, fsyncs what was written (file or folder
// tree) and renames it onto `target`. On an exception the temporary is removed and
// `target` is left untouched. Parent folders are created.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path& tmp)>& write);

// Convenience for text outputs (JSON, CSV, HTML).
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

}  // namespace vesica
