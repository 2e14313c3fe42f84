#include "SurfaceHeaderCheck.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "vesica/core/Error.h"

namespace vesica::io::detail {
namespace {

constexpr std::size_t kMaxPlyHeaderBytes = 64 * 1024;

std::uintmax_t scalar_bytes(const std::string& type) {
  static const std::map<std::string, std::uintmax_t> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto it = sizes.find(type);
  return it == sizes.end() ? 0 : it->second;
}

struct PlyElement {
  std::uintmax_t count = 0;
  std::uintmax_t min_bytes = 0;  // binary: scalars plus list counts (lists may be empty)
  int properties = 0;
};

}  // namespace

void check_ply_header(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(file, "cannot open the surface");
  std::string line;
  std::getline(in, line);
  if (line.rfind("ply", 0) != 0) fail(file, "not a PLY file (no \"ply\" magic line)");
  bool binary = false, have_format = false;
  std::vector<PlyElement> elements;
  while (true) {
    if (!std::getline(in, line) || static_cast<std::size_t>(in.tellg()) > kMaxPlyHeaderBytes)
      fail(file, "PLY header without \"end_header\" in its first 64 KiB");
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "end_header") break;
    if (keyword == "format") {
      std::string format;
      words >> format;
      binary = format != "ascii";
      have_format =
          format == "ascii" || format == "binary_little_endian" || format == "binary_big_endian";
    } else if (keyword == "element") {
      std::string name, count;
      words >> name >> count;
      if (count.empty() || !std::all_of(count.begin(), count.end(), ::isdigit) || count.size() > 12)
        fail(file, "PLY element \"" + name + "\" has no valid count");
      elements.push_back({std::stoull(count), 0, 0});
    } else if (keyword == "property") {
      if (elements.empty()) fail(file, "PLY property before any element");
      std::string type, count_type;
      words >> type;
      const std::string size_type = type == "list" ? (words >> count_type, count_type) : type;
      const std::uintmax_t bytes = scalar_bytes(size_type);
      if (bytes == 0) fail(file, "PLY property of unknown type \"" + size_type + "\"");
      elements.back().min_bytes += bytes;
      ++elements.back().properties;
    }
  }
  if (!have_format) fail(file, "PLY header without a known format line");
  const std::uintmax_t header_end = static_cast<std::uintmax_t>(in.tellg());
  const std::uintmax_t data = std::filesystem::file_size(path) - header_end;
  // ASCII: at least one digit and one separator per property value.
  std::uintmax_t needed = 0;
  for (const PlyElement& e : elements) {
    const std::uintmax_t per =
        binary ? e.min_bytes : 2u * static_cast<std::uintmax_t>(e.properties);
    if (per > 0 && e.count > data / per)
      fail(file,
           "PLY header promises " + std::to_string(e.count) + " elements but only " +
               std::to_string(data) + " bytes follow it",
           "the file is truncated or its header is wrong");
    needed += e.count * per;
  }
  if (needed > data)
    fail(
        file,
        "PLY header promises more data than the file's " + std::to_string(data) + " bytes after it",
        "the file is truncated or its header is wrong");
}

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
