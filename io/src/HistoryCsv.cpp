#include "vesica/io/HistoryCsv.h"

#include <sstream>

#include "vesica/core/AtomicOutput.h"
#include "vesica/core/Error.h"
#include "vesica/io/RecordingReader.h"

namespace vesica::io {
namespace {

constexpr const char* kHeader =
    "time_s,infused_ml,volume_ml,pves_cmh2o,pabd_cmh2o,pdet_cmh2o,flow_ml_s,voided_ml\n";

void require_column(const std::vector<double>& values, const Recording& r, const char* column) {
  if (values.empty() && r.rows() > 0)
    fail(r.source, std::string("has no column '") + column + "'",
         "history.csv columns: " + std::string(kHeader, std::string(kHeader).size() - 1));
}

}  // namespace

std::string history_csv_text(const std::vector<HistoryRow>& rows) {
  std::ostringstream s;
  s.precision(10);
  s << kHeader;
  for (const HistoryRow& r : rows)
    s << r.time_s << ',' << r.infused_ml << ',' << r.volume_ml << ',' << r.pves_cmh2o << ','
      << r.pabd_cmh2o << ',' << r.pdet_cmh2o << ',' << r.flow_ml_s << ',' << r.voided_ml << '\n';
  return s.str();
}

void write_history_csv(const std::vector<HistoryRow>& rows, const std::filesystem::path& csv) {
  write_text_atomically(csv, history_csv_text(rows));
}

Recording read_history_csv(const std::filesystem::path& csv) {
  ReaderOptions options;
  options.min_rows = 0;
  Recording r = read_recording(csv, options);
  require_column(r.volume_ml, r, "volume_ml");
  require_column(r.flow_ml_s, r, "flow_ml_s");
  return r;
}

std::vector<HistoryRow> history_rows(const Recording& r) {
  require_column(r.infused_ml, r, "infused_ml");
  require_column(r.volume_ml, r, "volume_ml");
  require_column(r.pves_cmh2o, r, "pves_cmh2o");
  require_column(r.pabd_cmh2o, r, "pabd_cmh2o");
  require_column(r.pdet_recorded_cmh2o, r, "pdet_cmh2o");
  require_column(r.flow_ml_s, r, "flow_ml_s");
  require_column(r.voided_ml, r, "voided_ml");
  std::vector<HistoryRow> rows(r.rows());
  for (std::size_t i = 0; i < rows.size(); ++i)
    rows[i] = {r.time_s[i],     r.infused_ml[i],          r.volume_ml[i], r.pves_cmh2o[i],
               r.pabd_cmh2o[i], r.pdet_recorded_cmh2o[i], r.flow_ml_s[i], r.voided_ml[i]};
  return rows;
}

}  // namespace vesica::io
