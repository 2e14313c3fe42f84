#include "vesica/io/CsvTable.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <vector>

#include "vesica/core/Error.h"
#include "vesica/core/InputFile.h"

namespace vesica::io {
namespace {

constexpr const char* kUtf8Bom = "\xEF\xBB\xBF";

void skip_byte_order_mark(std::string& first_line) {
  if (first_line.rfind(kUtf8Bom, 0) == 0) first_line.erase(0, 3);
}

bool all_empty(const std::vector<std::string>& cells) {
  return std::all_of(cells.begin(), cells.end(), [](const std::string& c) { return c.empty(); });
}

// One line into `text`, at most `max_bytes` of it: false at the end of the file. A longer
// line is an error before it is held in memory (a single 5 MB cell, a binary file).
bool next_line(std::istream& in, std::size_t max_bytes, int line, const std::string& file,
               std::string& text) {
  const LineRead r = read_line(in, text, max_bytes);
  if (r == LineRead::TooLong)
    fail(file,
         "line " + std::to_string(line) + " is longer than " + std::to_string(max_bytes) + " bytes",
         "not a CSV recording, or a cell holds far more than a value");
  return r == LineRead::Line;
}

// The lines that may be data rows (not blank, not a comment, not separators alone), the
// header included, counted over raw bytes and stopping once past `limit`: a table of too
// many rows is refused in a fraction of the time that parsing them would take.
std::size_t candidate_rows_up_to(std::istream& in, std::size_t limit) {
  std::vector<char> buffer(std::size_t{1} << 20);
  std::size_t count = 0;
  bool at_start = true, comment = false, content = false;
  while (count <= limit && in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < n; ++i) {
      const char c = buffer[i];
      if (c == '\n') {
        count += content && !comment;
        at_start = true, comment = false, content = false;
      } else if (c != ' ' && c != '\t' && c != '\r') {
        if (at_start) comment = c == '#';
        at_start = false;
        content = content || (c != ',' && c != ';' && c != '"');
      }
    }
  }
  return count + (content && !comment);
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

char detect_separator(const std::string& header_line) {
  constexpr std::array<char, 3> candidates = {',', ';', '\t'};
  std::array<std::size_t, 3> count{};
  bool quoted = false;
  for (char c : header_line) {
    if (c == '"') quoted = !quoted;
    if (quoted) continue;
    for (std::size_t k = 0; k < candidates.size(); ++k) count[k] += c == candidates[k];
  }
  const auto most = std::max_element(count.begin(), count.end());  // first on ties: ','
  return *most == 0 ? ',' : candidates[static_cast<std::size_t>(most - count.begin())];
}

void read_csv_rows(const std::filesystem::path& csv, const CsvOptions& options,
                   const std::function<void(const CsvHeader&)>& on_header,
                   const std::function<void(const std::vector<std::string>&, int)>& on_row) {
  const std::string file = csv.string();
  require_input_file(csv, kMaxTableFileBytes, "table");  // no pipe, no device, bounded
  std::ifstream in(csv, std::ios::binary);
  if (!in) fail(file, "cannot open the table", "check the path");
  if (candidate_rows_up_to(in, options.max_rows + 1) > options.max_rows + 1)
    fail(file, "more than " + std::to_string(options.max_rows) + " data rows",
         "downsample the recording (vesica reads at most that many rows)");
  in.clear();
  in.seekg(0);
  CsvHeader header;
  bool have_header = false;
  std::size_t rows = 0;
  std::string text;
  for (int line = 1; next_line(in, options.max_line_bytes, line, file, text); ++line) {
    if (line == 1) skip_byte_order_mark(text);
    const std::string t = trim(text);
    if (t.empty() || t[0] == '#') continue;
    if (!have_header) {
      header.separator = options.separator ? options.separator : detect_separator(t);
      header.names = split_csv_line(t, header.separator);
      have_header = true;
      on_header(header);
      continue;
    }
    const std::vector<std::string> cells = split_csv_line(t, header.separator);
    if (all_empty(cells)) continue;
    if (cells.size() != header.names.size())
      fail(file, "row " + std::to_string(line) + ": " + std::to_string(cells.size()) +
                     " cells, the header has " + std::to_string(header.names.size()));
    if (++rows > options.max_rows)
      fail(file, "more than " + std::to_string(options.max_rows) + " data rows",
           "downsample the recording (vesica reads at most that many rows)");
    on_row(cells, line);
  }
  if (in.bad()) fail(file, "could not be read to the end");
  if (!have_header) fail(file, "no header row", "the first non-comment line names the columns");
}

std::vector<std::string> read_leading_comments(const std::filesystem::path& csv,
                                               std::size_t max_lines) {
  const std::string file = csv.string();
  require_input_file(csv, kMaxTableFileBytes, "table");
  std::ifstream in(csv, std::ios::binary);
  std::vector<std::string> comments;
  std::string text;
  for (int line = 1;
       comments.size() < max_lines && next_line(in, kMaxCsvLineBytes, line, file, text); ++line) {
    if (line == 1) skip_byte_order_mark(text);
    const std::string t = trim(text);
    if (t.empty()) continue;
    if (t[0] != '#') break;  // the column header: the comments are over
    comments.push_back(t.substr(1));
  }
  return comments;
}

CsvTable read_csv_table(const std::filesystem::path& csv, const CsvOptions& options) {
  CsvTable table;
  read_csv_rows(
      csv, options,
      [&](const CsvHeader& h) {
        table.header = h.names;
        table.separator = h.separator;
      },
      [&](const std::vector<std::string>& cells, int line) {
        table.rows.push_back(cells);
        table.line.push_back(line);
      });
  return table;
}

}  // namespace vesica::io
