#include "SurfaceHeaderCheck.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

#include "vesica/core/Error.h"

namespace vesica::io::detail {

void check_stl_size(const std::filesystem::path& path) {
  const std::string file = path.string();
  const std::uintmax_t size = std::filesystem::file_size(path);
  std::ifstream in(path, std::ios::binary);
  char head[256] = {};
  in.read(head, sizeof head);
  const std::streamsize got = in.gcount();
  const bool text = std::all_of(head, head + got, [](char c) {
    return std::isprint(static_cast<unsigned char>(c)) ||
           std::isspace(static_cast<unsigned char>(c));
  });
  if (text && std::strncmp(head, "solid", 5) == 0) return;  // ASCII: the reader parses lines
  if (size < 84) fail(file, "too short for a binary STL (" + std::to_string(size) + " bytes)");
  std::uint32_t count = 0;
  std::memcpy(&count, head + 80, sizeof count);  // little-endian, as the format stores it
  if (84 + 50 * static_cast<std::uintmax_t>(count) > size)
    fail(file,
         "binary STL header says " + std::to_string(count) + " triangles, the file holds " +
             std::to_string((size - 84) / 50),
         "the file is truncated or its header is wrong");
}

}  // namespace vesica::io::detail
