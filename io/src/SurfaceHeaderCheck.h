#pragma once
// Internal: cheap checks of a file's header against its size, made before a reader
// allocates what the header claims (a VTK XML file or binary STL whose counts lie would
// otherwise take gigabytes, hang, or read past the data). PLY files are walked whole
// (PlyCheck.h), VTK XML files scanned whole (VtkXmlCheck.h).
#include <filesystem>

namespace vesica::io::detail {

// Throws vesica::Error naming the file when it is a binary STL whose triangle count does
// not fit its size (an ASCII STL is left to the reader).
void check_stl_size(const std::filesystem::path& path);

}  // namespace vesica::io::detail
