#pragma once
// A CSV file as text cells, the common layer of every table vesica reads (history.csv,
// urodynamic recordings): a header row naming the columns, then one row per sample.
//  - a UTF-8 byte-order mark before the header is skipped (spreadsheet exports carry one);
//  - blank lines and lines starting with '#' are comments;
//  - double quotes protect separators ("a, b") and "" is a literal quote;
//  - cells are trimmed of spaces, tabs and carriage returns.
// The separator is an option so that a European export (';') needs no second parser;
// decimal commas are the caller's to convert, cell by cell.
#include <filesystem>
#include <string>
#include <vector>

namespace vesica::io {

struct CsvOptions {
  char separator = ',';
};

struct CsvTable {
  std::vector<std::string> header;             // column names as written
  std::vector<std::vector<std::string>> rows;  // one cell per header column
  std::vector<int> line;                       // 1-based file line of each row

  std::size_t row_count() const { return rows.size(); }
};

// Throws vesica::Error naming the file when it cannot be opened, has no header row, or a
// row's cell count differs from the header's ("row 7: 3 cells, the header has 4").
CsvTable read_csv_table(const std::filesystem::path& csv, const CsvOptions& options = {});

// One line split into trimmed cells (quotes as above).
std::vector<std::string> split_csv_line(const std::string& line, char separator = ',');

// Text without surrounding spaces, tabs, carriage returns and newlines.
std::string trim(const std::string& text);

}  // namespace vesica::io
