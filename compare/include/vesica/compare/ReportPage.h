#pragma once
// The comparison report: one self-contained HTML page (inline SVG plots, the wall-stress
// PNG embedded as base64, no external resources) built from the analyses.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "vesica/compare/CalibrationResult.h"
#include "vesica/compare/RecordingAnalysis.h"
#include "vesica/compare/WallStressPicture.h"

namespace vesica::compare {

struct ReportInputs {
  const RecordingAnalysis* measured = nullptr;  // either may be absent
  const RecordingAnalysis* simulated = nullptr;
  const CalibrationResult* calibration = nullptr;
  std::optional<WallStressPicture> wall_stress;  // none when no mesh was available
  nlohmann::json comparison;                     // compare_models(), or null
};

std::string report_html(const ReportInputs& in);

}  // namespace vesica::compare
