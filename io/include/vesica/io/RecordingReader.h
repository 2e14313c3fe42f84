#pragma once
// Reads a urodynamic recording from CSV (the table rules of CsvTable.h: header row, '#'
// comment lines, a UTF-8 byte-order mark ignored), one row per sample, in clinical units
// (s, cmH2O, ml/s, ml). Measured recordings (any column names, mapped with ColumnMap) and
// the simulation's history.csv (HistoryCsv.h) go through the same code.
//
// Channels (keys) and the column names tried when the key is not mapped:
//   time    time_s, time_min, time            seconds, minutes, or mm:ss / hh:mm:ss cells
//   event   event, label, comment             free text
//   pves    pves_<unit>, pves                 pressure: cmh2o, kpa, pa, mmhg
//   pabd    pabd_<unit>, pabd
//   pdet    pdet_<unit>, pdet
//   flow    flow_ml_s, flow_ml_min, flow
//   voided  voided_ml, voided_l, voided
//   infused infused_ml, infused_l, infused
//   volume  volume_ml, volume_l, volume
// A column's unit is its suffix after the key ("pves_kpa") or a bracketed unit in a mapped
// name ("Pves [kPa]"); unsuffixed pressure columns use ReaderOptions::pressure_unit.
// Every recording needs a pressure (pdet, or pves and pabd). Its rows are ordered by
//  - time, with infused or bladder volume (a cystometry) or voided volume or flow (a
//    pressure-flow study): time must not go back;
//  - or, in a table read off at volume steps (as papers print them; no time column), by
//    the infused or bladder volume (a filling table) or the voided volume (a voiding
//    table), which must not go down.
// Errors (vesica::Error) name the file, the row (1-based file line) and the column.
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "vesica/io/Recording.h"

namespace vesica::io {

// key (time, event, pves, pabd, pdet, flow, voided, infused, volume) -> column name
using ColumnMap = std::map<std::string, std::string>;

// Parses "time=t,pves=Pves" into a ColumnMap; throws a usage error on unknown keys.
ColumnMap parse_column_map(const std::string& text);

struct ReaderOptions {
  ColumnMap columns;
  std::string pressure_unit = "cmh2o";  // for pressure columns without a unit
  std::size_t min_rows = 2;             // fewer data rows are an error
};

Recording read_recording(const std::filesystem::path& csv, const ReaderOptions& options = {});

// Parses one time cell ("06:20", "1:02:03", "380.5") into seconds; nullopt if malformed.
std::optional<double> parse_clock_time(const std::string& cell);

}  // namespace vesica::io
