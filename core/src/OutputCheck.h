#pragma once
// Internal to vesica_core: checks of a written temporary that catch what a library's
// writer did not report. Many writers (gmsh, ITK's NIfTI, VTK's PLY) ignore the return
// value of fwrite, so a full disk or a file-size limit leaves a cut file behind a call
// that "succeeded". A cut file is recognised without knowing its format by:
//  - a file that reached the process's file-size limit (ulimit -f): it was cut there;
//  - a file system left without a free block: the last write may have been cut;
//  - a gzip file (".gz") whose stream does not end properly or whose checksum is wrong.
#include <cstdint>
#include <filesystem>

namespace vesica::detail {

// Throws vesica::Error naming `target` when `written` (a file or a folder tree) shows one
// of the signs above.
void check_written(const std::filesystem::path& written, const std::filesystem::path& target);

// Before writing: throws vesica::Error naming `target` when `folder` (or the nearest folder
// above it that exists) has fewer than `total_bytes` free, or the file-size limit is below
// `largest_file_bytes`.
void check_room(const std::filesystem::path& folder, std::uintmax_t total_bytes,
                std::uintmax_t largest_file_bytes, const std::filesystem::path& target);

}  // namespace vesica::detail
