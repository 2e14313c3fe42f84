#include "SurfaceHeaderCheck.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "vesica/core/Error.h"

namespace vesica::io::detail {
namespace {

constexpr std::size_t kMaxXmlHeaderBytes = std::size_t{256} * 1024;
// zlib packs a run of equal bytes at most about 1032 to 1: more elements than that many per
// byte of the file cannot be in it.
constexpr double kMaxElementsPerByte = 1032.0;
constexpr std::uint64_t kMaxComponents = 64;

}  // namespace

void check_vtk_xml_counts(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(file, "cannot be opened");
  std::string head(kMaxXmlHeaderBytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<std::size_t>(in.gcount()));
  const auto appended = head.find("<AppendedData");
  if (appended != std::string::npos) head.resize(appended);
  const double bound = kMaxElementsPerByte * static_cast<double>(std::filesystem::file_size(path));
  static const std::regex count(R"re((NumberOf\w+)\s*=\s*"([^"]*)")re");
  for (std::sregex_iterator it(head.begin(), head.end(), count), end; it != end; ++it) {
    const std::string name = (*it)[1], value = (*it)[2];
    const bool digits =
        !value.empty() && value.size() <= 15 &&
        std::all_of(value.begin(), value.end(), [](char c) { return c >= '0' && c <= '9'; });
    const double n = digits ? std::stod(value) : -1.0;
    const bool components = name == "NumberOfComponents";
    if (!digits || (components ? n < 1 || n > kMaxComponents : n > bound))
      fail(file,
           name + "=\"" + single_line(value, 24) + "\" cannot be right for a file of " +
               std::to_string(std::filesystem::file_size(path)) + " bytes",
           "the file is damaged; write it again");
  }
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
