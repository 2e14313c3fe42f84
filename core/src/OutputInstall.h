#pragma once
// Internal to vesica_core: the last steps of an atomic output, shared by write_atomically
// and the staged outputs' commit.
#include <filesystem>

namespace vesica::detail {

// Renames the checked temporary `tmp` onto `target` (a folder replaces a folder in one
// exchange) and flushes the folder holding it. Throws vesica::Error naming `target`.
void install_output(const std::filesystem::path& tmp, const std::filesystem::path& target);

// fsync of a file or folder: the write-back errors (a full disk, an I/O error) that write()
// could not report. Throws vesica::Error naming `target`; a file system without fsync
// (EINVAL) is not an error.
void flush_to_disk(const std::filesystem::path& path, const std::filesystem::path& target);

// True when a component of `path` is a temporary output (".tmp-..."): files written there
// belong to a folder output still being written.
bool inside_temporary(const std::filesystem::path& path);

// The key under which an output is staged: absolute, normalised, no trailing separator.
std::filesystem::path output_key(const std::filesystem::path& target);

}  // namespace vesica::detail
