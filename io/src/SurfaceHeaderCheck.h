#pragma once
// Internal: cheap checks of a surface file's header against its size, made before a
// reader allocates what the header claims (a PLY or binary STL whose counts lie would
// otherwise take gigabytes or read past the data).
#include <filesystem>

namespace vesica::io::detail {

// Throws vesica::Error naming the file when its PLY header is malformed or its element
// counts cannot fit in the bytes that follow it.
void check_ply_header(const std::filesystem::path& path);

// Throws vesica::Error naming the file when it is a binary STL whose triangle count does
// not fit its size (an ASCII STL is left to the reader).
void check_stl_size(const std::filesystem::path& path);

}  // namespace vesica::io::detail
