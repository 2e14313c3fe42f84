#include "MshCheck.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

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

// gmsh trusts the sections' structure as well as their sizes: a physical group of
// dimension 65535, a negative node tag in an element or an element data view of 0
// components made its reader read out of bounds. Each line is checked in the section it
// belongs to; a view's header (string, real and integer tags) is followed to its data.
class SectionCheck {
 public:
  explicit SectionCheck(std::string file) : file_(std::move(file)) {}

  void line(const std::string& line, long number) {
    if (line.rfind("$End", 0) == 0) {
      section_.clear();
      return;
    }
    if (line[0] == '$') {
      section_ = line.substr(0, line.find_first_of(" \r"));
      first_ = true;
      view_stage_ = 0;
      components_ = 1;
      return;
    }
    std::istringstream in(line);
    std::vector<std::string> words;
    for (std::string w; in >> w && words.size() < 64;) words.push_back(w);
    if (words.empty()) return;
    if (section_ == "$PhysicalNames" && !first_) {
      if (!integer_token(words[0]) || std::strtol(words[0].c_str(), nullptr, 10) < 0 ||
          std::strtol(words[0].c_str(), nullptr, 10) > 3)
        refuse(number, "a physical group's dimension is not 0 to 3");
    } else if (section_ == "$Elements") {
      for (const std::string& w : words)
        if (!integer_token(w) || w[0] == '-')
          refuse(number, "an element line holds something other than tags and counts");
    } else if (section_ == "$ElementData" || section_ == "$NodeData") {
      view_line(words, number);
    }
    first_ = false;
  }

 private:
  [[noreturn]] void refuse(long number, const std::string& why) const {
    fail(file_, "line " + std::to_string(number) + ": " + why,
         "the file is damaged; save it again from Gmsh");
  }

  long count(const std::string& w, long number) const {
    if (!integer_token(w) || w[0] == '-') refuse(number, "a view's tag count is not a count");
    return std::strtol(w.c_str(), nullptr, 10);
  }

  // Stages: 0 string-tag count, 1 strings, 2 real-tag count, 3 reals, 4 integer-tag count,
  // 5 integers (time step, components, entities), 6 data lines "tag value...".
  void view_line(const std::vector<std::string>& words, long number) {
    switch (view_stage_) {
      case 0:
      case 2:
      case 4:
        left_ = count(words[0], number);
        integers_.clear();
        ++view_stage_;
        if (left_ == 0) ++view_stage_;
        break;
      case 1:
      case 3:
        if (--left_ == 0) ++view_stage_;
        break;
      case 5:
        integers_.push_back(count(words[0], number));
        if (--left_ == 0) {
          ++view_stage_;
          components_ = integers_.size() >= 2 ? integers_[1] : 1;
          if (components_ < 1 || components_ > 9)
            refuse(number, "a view of " + std::to_string(components_) + " components");
        }
        break;
      default:
        if (!integer_token(words[0]) || words[0][0] == '-' || words[0] == "0")
          refuse(number, "a view's value is for an element or node tag that is not one");
        if (static_cast<long>(words.size()) != components_ + 1)
          refuse(number,
                 "a view's line does not hold its " + std::to_string(components_) + " components");
    }
  }

  std::string file_;
  std::string section_;
  bool first_ = false;
  int view_stage_ = 0;
  long left_ = 0, components_ = 1;
  std::vector<long> integers_;
};

}  // namespace

void check_msh_file(const std::filesystem::path& path) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(file, "cannot be opened");
  const double bound =
      std::max(kMinTagBound, kTagsPerByte * static_cast<double>(std::filesystem::file_size(path)));
  std::string line;
  bool format_next = false, have_format = false;
  SectionCheck sections(file);
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
    if (!line.empty()) sections.line(line, number);
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
