#pragma once
// Internal: a PLY file walked from end to end before VTK's reader sees it. VTK's PLY
// parser trusts the file: a line with fewer values than its element has, a list count
// past the data, or a face naming a vertex that does not exist make it read outside its
// buffers (SIGSEGV, heap corruption). This walk reads every element as the header
// declares it, without storing it, and checks that each value is there and is a number,
// each list fits, and each face's vertex indices name existing vertices.
#include <filesystem>

namespace vesica::io::detail {

// Throws vesica::Error naming the file at the first problem (header, element, value).
void check_ply_file(const std::filesystem::path& path);

}  // namespace vesica::io::detail
