#pragma once
// A CSV file as text cells, the common layer of every table vesica reads (history.csv,
// urodynamic recordings): a header row naming the columns, then one row per sample.
//  - a UTF-8 byte-order mark before the header is skipped (spreadsheet exports carry one);
//  - blank lines, lines of empty cells only (";;;") and lines starting with '#' are
//    comments;
//  - the separator is ',', ';' or a tab: the one the header line uses most (outside
//    quotes), unless CsvOptions names one. A European export (';' separators, decimal
//    commas) thus needs no option; decimal commas are the caller's to convert, cell by
//    cell (CsvTable::decimal_comma says when they are possible);
//  - double quotes protect separators ("a, b") and "" is a literal quote;
//  - cells are trimmed of spaces, tabs and carriage returns.
// Files are streamed line by line and bounded: a line longer than max_line_bytes or more
// than max_rows data rows is an error naming the limit, before memory is spent on it.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace vesica::io {

// Hours of a 100 Hz recording; a longer file is not a urodynamic study.
inline constexpr std::size_t kMaxCsvRows = 2'000'000;
inline constexpr std::size_t kMaxCsvLineBytes = 64 * 1024;

struct CsvOptions {
  char separator = 0;  // 0: detected from the header line
  std::size_t max_rows = kMaxCsvRows;
  std::size_t max_line_bytes = kMaxCsvLineBytes;
};

struct CsvHeader {
  std::vector<std::string> names;  // column names as written
  char separator = ',';
  bool decimal_comma() const { return separator != ','; }
};

// Calls on_header once with the header row, then on_row for each data row with its cells
// (one per header column) and its 1-based file line. Throws vesica::Error naming the file
// when it cannot be opened, has no header row, a line is too long, there are too many rows,
// or a row's cell count differs from the header's ("row 7: 3 cells, the header has 4").
void read_csv_rows(const std::filesystem::path& csv, const CsvOptions& options,
                   const std::function<void(const CsvHeader&)>& on_header,
                   const std::function<void(const std::vector<std::string>&, int)>& on_row);

struct CsvTable {
  std::vector<std::string> header;             // column names as written
  std::vector<std::vector<std::string>> rows;  // one cell per header column
  std::vector<int> line;                       // 1-based file line of each row
  char separator = ',';

  std::size_t row_count() const { return rows.size(); }
};

// The comment lines ('#' removed) before the header row, at most `max_lines` of them, each
// within the line bound (a longer one is an error, as for the rows).
std::vector<std::string> read_leading_comments(const std::filesystem::path& csv,
                                               std::size_t max_lines = 200);

// The whole table in memory (read_csv_rows's rules and errors).
CsvTable read_csv_table(const std::filesystem::path& csv, const CsvOptions& options = {});

// One line split into trimmed cells (quotes as above).
std::vector<std::string> split_csv_line(const std::string& line, char separator = ',');

// The separator a header line uses most outside quotes: ',', ';' or tab (',' when none).
char detect_separator(const std::string& header_line);

// Text without surrounding spaces, tabs, carriage returns and newlines.
std::string trim(const std::string& text);

}  // namespace vesica::io
