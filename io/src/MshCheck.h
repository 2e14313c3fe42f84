#pragma once
// Internal: a .msh file checked before gmsh opens it. gmsh sizes its arrays by the counts
// and largest tags a file states (a tag of 1.2e9 in a 2 KB file made it allocate 9.7 GB),
// and reads binary files without bounds. So only ASCII MSH 2.2 and 4.x files are opened,
// and no integer in them may exceed what a file of their size can describe; sections whose
// structure gmsh trusts (physical names, elements, element and node data) are checked too.
#include <filesystem>

namespace vesica::io::detail {

// Throws vesica::Error naming the file when it is not ASCII MSH 2.2/4.x or an integer in it
// (a count, a tag) is out of proportion to the file's size.
void check_msh_file(const std::filesystem::path& path);

}  // namespace vesica::io::detail
