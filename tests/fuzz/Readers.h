#pragma once
// The readers under the fuzz label: each with the valid files its mutations start from
// (made by vesica's own writers or taken from the repository) and what a stage does with
// the file it is given.
#include <filesystem>
#include <string>
#include <vector>

namespace vesica::fuzz {

struct Reader {
  std::string name;       // as given on the command line: "stl", "dicom", ...
  std::string extension;  // of the case file (".stl"); empty for a DICOM folder
  // Writes the seed files into `dir` (one or more, any names) and returns them.
  std::vector<std::filesystem::path> (*make_seeds)(const std::filesystem::path& dir);
  // Reads the case the way the stage does; throws vesica::Error to refuse it.
  void (*read)(const std::filesystem::path& input);
};

const std::vector<Reader>& readers();

}  // namespace vesica::fuzz
