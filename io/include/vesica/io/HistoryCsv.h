#pragma once
// history.csv, the simulation's cystometry as one row per step, in clinical units named by
// the column suffixes:
//   time_s, infused_ml, volume_ml, pves_cmh2o, pabd_cmh2o, pdet_cmh2o, flow_ml_s, voided_ml
// (10 significant digits). It is read back through the recording reader
// (RecordingReader.h), so compare, the runner's studies and any user script see the same
// columns with the same units.
#include <filesystem>
#include <string>
#include <vector>

#include "vesica/io/Recording.h"

namespace vesica::io {

struct HistoryRow {
  double time_s = 0.0;
  double infused_ml = 0.0;
  double volume_ml = 0.0;
  double pves_cmh2o = 0.0;
  double pabd_cmh2o = 0.0;
  double pdet_cmh2o = 0.0;
  double flow_ml_s = 0.0;
  double voided_ml = 0.0;
};

// The file's text: the header line, then one line per row.
std::string history_csv_text(const std::vector<HistoryRow>& rows);

// Writes the text atomically (temporary sibling, then rename).
void write_history_csv(const std::vector<HistoryRow>& rows, const std::filesystem::path& csv);

// Reads a history.csv (or any recording with time, volume_ml, pdet or pves and pabd, and
// flow_ml_s columns; others may be missing). A failed run's short history is accepted:
// zero data rows are not an error. Throws vesica::Error naming the file and the column.
Recording read_history_csv(const std::filesystem::path& csv);

// The rows of a history read back; throws vesica::Error naming recording.source when one
// of the eight columns is missing.
std::vector<HistoryRow> history_rows(const Recording& recording);

}  // namespace vesica::io
