#pragma once
// A recording with one known mistake made to it, for the tests of what vesica does with a
// file whose numbers cannot be what its columns say: the rows of `from` (comma-separated),
// each data row's cells passed through `edit`, written to `to`, comments and header as
// they were (`first_line`, when given, before them).
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

namespace vesica::test {

inline void write_edited_recording(const std::filesystem::path& from,
                                   const std::filesystem::path& to,
                                   const std::function<void(std::vector<std::string>&)>& edit,
                                   const std::string& first_line = "") {
  std::ifstream in(from);
  std::ofstream out(to);
  if (!first_line.empty()) out << first_line << "\n";
  bool header = false;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || !header) {
      header = header || (!line.empty() && line[0] != '#');
      out << line << "\n";
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    edit(cells);
    for (std::size_t k = 0; k < cells.size(); ++k) out << (k ? "," : "") << cells[k];
    out << "\n";
  }
}

}  // namespace vesica::test
