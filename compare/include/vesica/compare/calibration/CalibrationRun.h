#pragma once
// Entry point from vesica-compare into the calibration: parses --calibrate and runs the
// fit when vesica was built with the simulate library; otherwise says so (usage error).
#include "vesica/compare/CompareRun.h"
#include "vesica/compare/analysis/ModelComparison.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/calibration/CalibrationResult.h"

namespace vesica::compare {

CalibrationResult calibrate_from_options(const CompareOptions& options,
                                         const RecordingAnalysis& measured,
                                         const ComparisonOptions& comparison);

}  // namespace vesica::compare
