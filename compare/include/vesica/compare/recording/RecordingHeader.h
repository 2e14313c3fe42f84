#pragma once
// What the comment lines at the top of a recording ("# ...", before the column header)
// say about the patient and the study, for the report's header: sex, age and a stated fill
// rate, read from free text ("adult female, 34 years", "a 68-year-old man") or key: value
// lines ("sex: F", "age: 68"). Nothing patient-identifying is kept besides these.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "vesica/compare/analysis/SexSpecificCriteria.h"

namespace vesica::compare {

struct RecordingHeader {
  Sex sex = Sex::unknown;
  std::optional<double> age_years;
  std::optional<double> stated_fill_rate_ml_min;
};

RecordingHeader parse_recording_header(const std::vector<std::string>& comment_lines);
// The leading '#' lines of `csv`, read within the CSV reader's bounds (empty when it
// cannot be read: the recording reader reports that). Scanned word by word, never with a
// regular expression: a header line is unbounded user text.
RecordingHeader read_recording_header(const std::filesystem::path& csv);

}  // namespace vesica::compare
