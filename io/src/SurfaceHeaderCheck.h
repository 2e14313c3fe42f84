#pragma once
// Internal: cheap checks of a file's header against its size, made before a reader
// allocates what the header claims (a VTK XML file or binary STL whose counts lie would
// otherwise take gigabytes, hang, or read past the data). PLY files are walked whole
// (PlyCheck.h).
#include <filesystem>

namespace vesica::io::detail {

// Throws vesica::Error naming the file when a count of its VTK XML header (NumberOfPoints,
// NumberOfCells, NumberOfPolys, NumberOfComponents, ...) is not a number or cannot fit
// in the file: VTK's XML readers allocate what the header says (a NumberOfComponents of
// 2^64 hangs them).
void check_vtk_xml_counts(const std::filesystem::path& path);

// Throws vesica::Error naming the file when it is a binary STL whose triangle count does
// not fit its size (an ASCII STL is left to the reader).
void check_stl_size(const std::filesystem::path& path);

}  // namespace vesica::io::detail
