#pragma once
// vesica-segment's parameter table: every option of the command line and every `params`
// key of a segment stage in a pipeline file, with unit, range, help and the default of the
// settings it is bound to (SegmentParams.h). Its library depends only on core and this
// header includes nothing heavy, so the runner links it to check pipeline files before
// any stage runs. The input, output and the series choice (--series, --list-series) are
// not parameters: a series is named by a key of its UID, which the manifest's parameters
// must not carry.
#include <string>

#include "vesica/core/ParameterTable.h"
#include "vesica/segment/SegmentParams.h"

namespace vesica::segment {

// What the table fills.
struct SegmentSettings {
  SegmentParams params;           // its modality is set once `modality` is resolved
  std::string modality = "auto";  // auto (the DICOM header; CT for volume files), ct or mr
};

ParameterTable parameter_table(SegmentSettings& settings);
// Bound to default settings of its own (the runner's copy).
ParameterTable parameter_table();

}  // namespace vesica::segment
