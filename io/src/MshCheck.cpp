#include "MshCheck.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"

namespace vesica::io::detail {
namespace {

// Tags and counts at most this many per byte of the file (a node line holds more than
// ten bytes), and never fewer than a million (sparse tags of small files).
constexpr double kTagsPerByte = 64.0;
constexpr double kMinTagBound = 1e6;
constexpr std::size_t kMaxLineBytes = std::size_t{64} * 1024;

bool integer_token(const std::string& w) {
  const std::size_t first = w[0] == '-' ? 1 : 0;
  return w.size() > first && w.size() <= 30 &&
         std::all_of(w.begin() + static_cast<long>(first), w.end(),
                     [](char c) { return c >= '0' && c <= '9'; });
}

void check_format_line(const std::string& line, const std::string& file) {
  std::istringstream words(line);
  std::string version;
  int file_type = -1;
  words >> version >> file_type;
  if (version != "2.2" && version != "4" && version != "4.1")
    fail(file, "MSH version \"" + single_line(version, 20) + "\" is not 2.2 or 4.1",
         "save the mesh from Gmsh as MSH 4.1");
  if (file_type != 0)
    fail(file, "binary .msh files are not read", "save it from Gmsh as ASCII (Mesh.Binary=0)");
}

}  // namespace

void check_msh_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(file, "cannot be opened");
  const double bound =
      std::max(kMinTagBound, kTagsPerByte * static_cast<double>(std::filesystem::file_size(path)));
  std::string line;
  bool format_next = false, have_format = false;
  for (long number = 1;; ++number) {
    const LineRead r = read_line(in, line, kMaxLineBytes);
    if (r == LineRead::End) break;
    if (r == LineRead::TooLong)
      fail(file, "line " + std::to_string(number) + " is longer than 64 KiB");
    if (format_next) {
      check_format_line(line, file);
      format_next = false;
      have_format = true;
      continue;
    }
    if (line.rfind("$MeshFormat", 0) == 0) format_next = true;
    std::istringstream words(line);
    for (std::string w; words >> w;)
      if (integer_token(w) && std::abs(std::strtod(w.c_str(), nullptr)) > bound)
        fail(file,
             "line " + std::to_string(number) + ": the count or tag " + single_line(w, 24) +
                 " cannot be right for a file of " +
                 std::to_string(std::filesystem::file_size(path)) + " bytes",
             "the file is damaged; save it again from Gmsh");
  }
  if (!have_format) fail(file, "not a Gmsh .msh file (no $MeshFormat section)");
}

}  // namespace vesica::io::detail
