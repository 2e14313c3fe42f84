#pragma once
// Internal: a VTK XML file (.vtp, .vtu) checked against its own size before VTK's reader
// allocates what it declares. VTK trusts two kinds of numbers:
//  - the counts of the XML (NumberOfPoints, NumberOfCells, NumberOfComponents, ...): a
//    NumberOfComponents of 2^64 hangs the reader;
//  - the header in front of each binary array: its byte count, or, compressed
//    (vtkZLibDataCompressor), its block count, block size and compressed block sizes. A
//    block count of 0xF0000000 in a 14 KB file made VTK allocate and zero-fill 15 GB.
// Every count must fit the file (zlib packs at most about 1032 bytes into one); every
// binary header must lie inside the file and its blocks with it. The XML is scanned by
// hand, tag by tag, in one pass: no regular expression over text a user wrote.
#include <filesystem>

namespace vesica::io::detail {

// Throws vesica::Error naming the file and the first number that cannot be right.
void check_vtk_xml_counts(const std::filesystem::path& path);

}  // namespace vesica::io::detail
