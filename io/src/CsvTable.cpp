#include "vesica/io/CsvTable.h"

#include <fstream>

#include "vesica/core/Error.h"

namespace vesica::io {
namespace {

constexpr const char* kUtf8Bom = "\xEF\xBB\xBF";

void skip_byte_order_mark(std::string& first_line) {
  if (first_line.rfind(kUtf8Bom, 0) == 0) first_line.erase(0, 3);
}

}  // namespace

std::string trim(const std::string& text) {
  const auto b = text.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = text.find_last_not_of(" \t\r\n");
  return text.substr(b, e - b + 1);
}

std::vector<std::string> split_csv_line(const std::string& line, char separator) {
  std::vector<std::string> cells(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        cells.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        cells.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == separator) {
      cells.emplace_back();
    } else {
      cells.back() += c;
    }
  }
  for (auto& cell : cells) cell = trim(cell);
  return cells;
}

CsvTable read_csv_table(const std::filesystem::path& csv, const CsvOptions& options) {
  const std::string file = csv.string();
  std::ifstream in(csv);
  if (!in) fail(file, "cannot open the table", "check the path");
  CsvTable table;
  bool have_header = false;
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    if (line == 1) skip_byte_order_mark(text);
    const std::string t = trim(text);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> cells = split_csv_line(t, options.separator);
    if (!have_header) {
      table.header = std::move(cells);
      have_header = true;
      continue;
    }
    if (cells.size() != table.header.size())
      fail(file, "row " + std::to_string(line) + ": " + std::to_string(cells.size()) +
                     " cells, the header has " + std::to_string(table.header.size()));
    table.rows.push_back(std::move(cells));
    table.line.push_back(line);
  }
  if (!have_header) fail(file, "no header row", "the first non-comment line names the columns");
  return table;
}

}  // namespace vesica::io
