// Built instead of the calibration when the simulate library is not available.
#include "vesica/compare/calibration/CalibrationRun.h"
#include "vesica/core/Error.h"

namespace vesica::compare {

CalibrationResult calibrate_from_options(const CompareOptions&, const RecordingAnalysis&,
                                         const ComparisonOptions&) {
  usage_error("--calibrate: this build has no simulate library",
              "build vesica with simulate/ to calibrate");
}

}  // namespace vesica::compare
