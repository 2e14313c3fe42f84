#include "vesica/io/RecordingReader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <vector>

#include "LowerCase.h"
#include "vesica/core/Error.h"
#include "vesica/core/Units.h"
#include "vesica/io/CsvTable.h"

namespace vesica::io {
namespace {

enum class Quantity { Time, Text, Pressure, Flow, Volume };

struct Channel {
  const char* key;
  Quantity quantity;
  std::vector<std::string> plain_names;  // accepted unsuffixed names besides the key
};

// Besides the key, a channel answers to the names of the ICS standard (Pves, Pabd, Pdet,
// Qura, Vura, Vinf) and to the spellings urodynamic systems commonly export; headers are
// compared in lower case.
const std::vector<Channel>& channels() {
  static const std::vector<Channel> all = {
      {"time", Quantity::Time, {"t", "elapsed time"}},
      {"event", Quantity::Text, {"label", "comment", "events", "marker"}},
      {"pves", Quantity::Pressure, {"p ves", "p_ves", "p-ves", "p.ves", "vesical pressure"}},
      {"pabd", Quantity::Pressure, {"p abd", "p_abd", "p-abd", "p.abd", "abdominal pressure"}},
      {"pdet", Quantity::Pressure, {"p det", "p_det", "p-det", "p.det", "detrusor pressure"}},
      {"flow", Quantity::Flow, {"qura", "q ura", "uroflow", "flow rate", "urine flow"}},
      {"voided", Quantity::Volume, {"vura", "v ura", "voided volume", "vvoid", "voided_volume"}},
      {"infused",
       Quantity::Volume,
       {"vinf", "v inf", "infused volume", "vinfus", "infused_volume"}},
      {"volume", Quantity::Volume, {"vbladder", "bladder volume"}},
  };
  return all;
}

bool names_channel(const Channel& ch, const std::string& lower_name) {
  return lower_name == ch.key || std::find(ch.plain_names.begin(), ch.plain_names.end(),
                                           lower_name) != ch.plain_names.end();
}

bool names_any_channel(const std::string& lower_name) {
  return std::any_of(channels().begin(), channels().end(),
                     [&](const Channel& c) { return names_channel(c, lower_name); });
}

// Factor from a unit (lowercase, "_" or "/" separated) to the channel's clinical unit;
// nullopt when the unit is unknown for that quantity.
std::optional<double> unit_factor(Quantity q, std::string unit) {
  std::replace(unit.begin(), unit.end(), '/', '_');
  if (q == Quantity::Pressure) {
    if (unit == "cmh2o") return 1.0;
    if (unit == "kpa") return 1e3 / units::kPaPerCmH2O;
    if (unit == "pa") return 1.0 / units::kPaPerCmH2O;
    if (unit == "mmhg") return 133.322387415 / units::kPaPerCmH2O;
  } else if (q == Quantity::Flow) {
    if (unit == "ml_s") return 1.0;
    if (unit == "ml_min") return 1.0 / units::kSecondsPerMinute;
  } else if (q == Quantity::Volume) {
    if (unit == "ml") return 1.0;
    if (unit == "l") return 1000.0;
  } else if (q == Quantity::Time) {
    if (unit == "s") return 1.0;
    if (unit == "min") return units::kSecondsPerMinute;
  }
  return std::nullopt;
}

const char* unit_hint(Quantity q) {
  switch (q) {
    case Quantity::Pressure:
      return "pressure units: cmh2o, kpa, pa, mmhg";
    case Quantity::Flow:
      return "flow units: ml_s, ml_min";
    case Quantity::Volume:
      return "volume units: ml, l";
    case Quantity::Time:
      return "time units: s, min, or mm:ss cells";
    case Quantity::Text:
      return "";
  }
  return "";
}

struct BoundColumn {
  const Channel* channel = nullptr;
  std::size_t index = 0;
  std::string header;
  double factor = 1.0;
};

// A bracketed unit in a header: "Pves [kPa]" or "Pves (kPa)".
std::optional<std::string> bracket_unit(const std::string& header) {
  const auto open = header.find_first_of("[(");
  if (open == std::string::npos) return std::nullopt;
  const auto close = header.find_first_of("])", open);
  if (close == std::string::npos) return std::nullopt;
  std::string u = detail::lower_case(trim(header.substr(open + 1, close - open - 1)));
  u.erase(std::remove(u.begin(), u.end(), ' '), u.end());
  return u;
}

std::string column_place(const std::string& header) {
  return "row 1, column \"" + single_line(header, 40) + "\"";
}

// "columns: a, b, c" as a hint for a file whose columns were not recognised.
std::string columns_found(const std::vector<std::string>& header) {
  std::string list;
  for (const std::string& h : header) list += (list.empty() ? "" : ", ") + h;
  return "its columns: " + single_line(list, 100);
}

double default_factor(const Channel& ch, const ReaderOptions& options, const std::string& file,
                      const std::string& header) {
  if (ch.quantity != Quantity::Pressure) return 1.0;
  const auto f = unit_factor(Quantity::Pressure, detail::lower_case(options.pressure_unit));
  if (!f)
    fail(file, column_place(header) + ": unknown pressure unit \"" + options.pressure_unit + "\"",
         unit_hint(Quantity::Pressure));
  return *f;
}

// Unit of a column found by its default name: "<name>_<unit>", "<name> [unit]" or the bare
// name. A bracket holding another name rather than a unit ("flow (Qura)") is a gloss.
std::optional<BoundColumn> bind_default(const Channel& ch, const std::vector<std::string>& header,
                                        const ReaderOptions& options, const std::string& file) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string h = detail::lower_case(trim(header[i]));
    if (const auto bu = bracket_unit(h)) {
      const std::string base = trim(h.substr(0, h.find_first_of("[(")));
      if (!names_channel(ch, base)) continue;
      if (names_any_channel(*bu))
        return BoundColumn{&ch, i, header[i], default_factor(ch, options, file, header[i])};
      const auto f = unit_factor(ch.quantity, *bu);
      if (!f)
        fail(file, column_place(header[i]) + ": unknown unit \"" + *bu + "\"",
             unit_hint(ch.quantity));
      return BoundColumn{&ch, i, header[i], *f};
    }
    if (names_channel(ch, h))
      return BoundColumn{&ch, i, header[i], default_factor(ch, options, file, header[i])};
    if (ch.quantity == Quantity::Text) continue;
    // Another spelling with a unit suffix ("qura_ml_s"): only when the suffix is a unit.
    for (const std::string& name : ch.plain_names)
      if (h.rfind(name + "_", 0) == 0)
        if (const auto f = unit_factor(ch.quantity, h.substr(name.size() + 1)))
          return BoundColumn{&ch, i, header[i], *f};
    const std::string prefix = std::string(ch.key) + "_";
    if (h.rfind(prefix, 0) == 0) {
      const std::string unit = h.substr(prefix.size());
      const auto f = unit_factor(ch.quantity, unit);
      if (!f)
        fail(file, column_place(header[i]) + ": unknown unit \"" + unit + "\"",
             unit_hint(ch.quantity));
      return BoundColumn{&ch, i, header[i], *f};
    }
  }
  return std::nullopt;
}

// Unit of a mapped column: bracketed unit, else a known "_<unit>" suffix, else the default.
BoundColumn bind_mapped(const Channel& ch, const std::string& name,
                        const std::vector<std::string>& header, const ReaderOptions& options,
                        const std::string& file) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (detail::lower_case(header[i]) != detail::lower_case(trim(name))) continue;
    if (ch.quantity == Quantity::Text) return BoundColumn{&ch, i, header[i], 1.0};
    if (const auto bu = bracket_unit(header[i])) {
      const auto f = unit_factor(ch.quantity, *bu);
      if (!f)
        fail(file, column_place(header[i]) + ": unknown unit \"" + *bu + "\"",
             unit_hint(ch.quantity));
      return BoundColumn{&ch, i, header[i], *f};
    }
    const std::string h = detail::lower_case(header[i]);
    for (std::size_t p = h.find('_'); p != std::string::npos; p = h.find('_', p + 1))
      if (const auto f = unit_factor(ch.quantity, h.substr(p + 1)))
        return BoundColumn{&ch, i, header[i], *f};
    return BoundColumn{&ch, i, header[i], default_factor(ch, options, file, header[i])};
  }
  fail(file, "missing column \"" + name + "\" (mapped to " + ch.key + ")",
       "check --columns against the header row");
}

std::optional<double> parse_number(const std::string& cell) {
  if (cell.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (end != cell.c_str() + cell.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// "12,5" in a table separated by ';' or tabs (a European export) is 12.5. A cell with both
// a comma and a point ("1.234,5") is left alone and refused: its grouping is ambiguous.
std::string with_decimal_point(const std::string& cell, bool decimal_comma) {
  if (!decimal_comma || cell.find('.') != std::string::npos) return cell;
  const auto comma = cell.find(',');
  if (comma == std::string::npos || cell.find(',', comma + 1) != std::string::npos) return cell;
  std::string s = cell;
  s[comma] = '.';
  return s;
}

// A cell as quoted in an error: short, so that the line stays readable.
std::string quoted_cell(const std::string& cell) {
  return "\"" + single_line(cell, 40) + "\"";
}

std::string format_number(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

std::string format_seconds(double s) {
  return format_number(s) + " s";
}

std::vector<double>* target(Recording& r, const std::string& key) {
  if (key == "time") return &r.time_s;
  if (key == "pves") return &r.pves_cmh2o;
  if (key == "pabd") return &r.pabd_cmh2o;
  if (key == "pdet") return &r.pdet_recorded_cmh2o;
  if (key == "flow") return &r.flow_ml_s;
  if (key == "voided") return &r.voided_ml;
  if (key == "infused") return &r.infused_ml;
  if (key == "volume") return &r.volume_ml;
  return nullptr;
}

std::vector<BoundColumn> bind_columns(const std::vector<std::string>& header,
                                      const ReaderOptions& options, const std::string& file) {
  std::vector<BoundColumn> bound;
  for (const auto& ch : channels()) {
    const auto mapped = options.columns.find(ch.key);
    if (mapped != options.columns.end()) {
      bound.push_back(bind_mapped(ch, mapped->second, header, options, file));
    } else if (auto b = bind_default(ch, header, options, file)) {
      bound.push_back(*b);
    }
  }
  auto has = [&](const char* key) {
    return std::any_of(bound.begin(), bound.end(),
                       [&](const BoundColumn& b) { return std::string(b.channel->key) == key; });
  };
  // The fix first: a long header list is what the one-line cap may cut, never the fix.
  const std::string hint = "map one with --columns KEY=NAME; " + columns_found(header);
  if (!has("pdet") && !(has("pves") && has("pabd")))
    fail(file, "missing columns for pressure (pdet_cmh2o, or pves_cmh2o and pabd_cmh2o)", hint);
  const bool filled = has("infused") || has("volume");
  if (has("time") && !filled && !has("voided") && !has("flow"))
    fail(file, "missing column for volume (infused_ml, volume_ml, voided_ml or flow_ml_s)", hint);
  if (!has("time") && !filled && !has("voided"))
    fail(file,
         "missing column for time, or for the volume a table without time is read at "
         "(infused_ml or volume_ml: filling; voided_ml: voiding)",
         hint);
  return bound;
}

// The channel that orders the rows: time, else (a table read off at volume steps) the
// infused, bladder or voided volume.
const char* row_order_key(const std::vector<BoundColumn>& bound) {
  for (const char* key : {"time", "infused", "volume", "voided"})
    for (const auto& b : bound)
      if (std::string(b.channel->key) == key) return key;
  return "time";
}

// One cell into its channel; the channel that orders the rows (order_key) must not go back.
void read_cell(const BoundColumn& b, const std::string& cell, int line, bool decimal_comma,
               const std::string& file, const std::string& order_key, Recording& r) {
  if (b.channel->quantity == Quantity::Text) {
    r.event.push_back(cell);
    return;
  }
  const std::string place = "row " + std::to_string(line) + ", column " + quoted_cell(b.header) +
                            ": " + quoted_cell(cell);
  std::optional<double> v;
  if (b.channel->quantity == Quantity::Time && cell.find(':') != std::string::npos)
    v = parse_clock_time(with_decimal_point(cell, decimal_comma));
  else if (const auto n = parse_number(with_decimal_point(cell, decimal_comma)))
    v = *n * b.factor;
  if (!v) fail(file, place + " is not a number");
  auto* values = target(r, b.channel->key);
  if (b.channel->key == order_key && !values->empty() && *v < values->back()) {
    if (b.channel->quantity == Quantity::Time)
      fail(file,
           place + " goes back in time (" + format_seconds(*v) + " after " +
               format_seconds(values->back()) + ")",
           "rows must be sorted by time");
    fail(file, place + " is below the row before it (" + format_number(values->back()) + ")",
         "a table without time must be sorted by its volume");
  }
  values->push_back(*v);
}

}  // namespace

std::optional<double> parse_clock_time(const std::string& cell) {
  std::vector<std::string> parts;
  std::stringstream ss(cell);
  for (std::string p; std::getline(ss, p, ':');) parts.push_back(trim(p));
  if (parts.size() < 2 || parts.size() > 3) return std::nullopt;
  double seconds = 0.0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const auto v = parse_number(parts[i]);
    if (!v || *v < 0) return std::nullopt;
    if (i > 0 && *v >= 60.0) return std::nullopt;
    seconds = seconds * 60.0 + *v;
  }
  return seconds;
}

ColumnMap parse_column_map(const std::string& text) {
  ColumnMap map;
  std::stringstream ss(text);
  for (std::string item; std::getline(ss, item, ',');) {
    if (trim(item).empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos) usage_error("--columns: \"" + item + "\" is not KEY=NAME");
    const std::string key = detail::lower_case(trim(item.substr(0, eq)));
    const bool known = std::any_of(channels().begin(), channels().end(),
                                   [&](const Channel& c) { return key == c.key; });
    if (!known)
      usage_error("--columns: unknown key \"" + key + "\"",
                  "keys: time, event, pves, pabd, pdet, flow, voided, infused, volume");
    map[key] = trim(item.substr(eq + 1));
  }
  return map;
}

Recording read_recording(const std::filesystem::path& csv, const ReaderOptions& options) {
  const std::string file = csv.string();
  if (!std::filesystem::exists(csv)) fail(file, "cannot open the recording", "check the path");
  if (std::filesystem::is_directory(csv)) fail(file, "is a folder, not a recording");
  // Rows are converted as they are read: a long recording never exists as text cells.
  std::vector<BoundColumn> bound;
  bool decimal_comma = false;
  std::string order_key;
  Recording r;
  r.source = file;
  read_csv_rows(
      csv, CsvOptions{},
      [&](const CsvHeader& header) {
        bound = bind_columns(header.names, options, file);
        decimal_comma = header.decimal_comma();
        order_key = row_order_key(bound);
      },
      [&](const std::vector<std::string>& cells, int line) {
        r.line.push_back(line);
        for (const auto& b : bound)
          read_cell(b, cells[b.index], line, decimal_comma, file, order_key, r);
      });
  if (r.rows() < options.min_rows)
    fail(file, options.min_rows == 2
                   ? "fewer than two data rows"
                   : "fewer than " + std::to_string(options.min_rows) + " data rows");
  // The rows must span something: a time column stuck at one value has no axis to plot
  // or rates to compute.
  const std::vector<double>& order = *target(r, order_key);
  if (!order.empty() && !(order.back() > order.front()))
    fail(file,
         order_key == "time"
             ? "time never advances (every row at " + format_seconds(order.front()) + ")"
             : "the " + order_key + " volume never changes (every row at " +
                   format_number(order.front()) + " ml)",
         "the rows must span the study");
  return r;
}

}  // namespace vesica::io
