#pragma once
// The comparison report: one self-contained HTML page (inline SVG plots, the wall-stress
// PNG embedded as base64, no external resources), laid out for a urologist: the header
// (recording and model settings), the stacked multichannel trace, the filling, flow and
// pressure-flow plots, the parameter table with normal ranges, the sex-specific criteria,
// the wall stress at capacity, then the model-against-measurement details. It fits a
// 1280-px window and prints to A4 (report.pdf).
#include <filesystem>
#include <optional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/analysis/SexSpecificCriteria.h"
#include "vesica/compare/analysis/SimulatedModel.h"
#include "vesica/compare/calibration/CalibrationResult.h"
#include "vesica/compare/report/FluidJetPicture.h"
#include "vesica/compare/report/WallStressPicture.h"
#include "vesica/compare/report/WallViewer.h"

namespace vesica::compare {

// What the report says about the patient (never a name or an identifier).
struct PatientFacts {
  Sex sex = Sex::unknown;
  std::string sex_source;  // "recording header", "--sex", or empty
  std::optional<double> age_years;
  std::optional<double> stated_fill_rate_ml_min;
};

struct ReportInputs {
  const RecordingAnalysis* measured = nullptr;  // either may be absent
  const RecordingAnalysis* simulated = nullptr;
  const CalibrationResult* calibration = nullptr;
  std::optional<WallStressPicture> wall_stress;  // none when no frame was available
  std::optional<FluidJetPicture> fluid_jet;      // level 2's jet at Qmax; none at level 1
  std::optional<WallViewer> wall_viewer;         // the interactive wall; none without a series
  std::filesystem::path three_js_dir;            // where three.min.js is inlined from
  const nlohmann::json* comparison = nullptr;    // compare_models(), or none
  PatientFacts patient;
  std::optional<SimulatedModel> model;  // of the simulated recording
  std::string generated_utc;            // when the report was made
};

std::string report_html(const ReportInputs& in);

}  // namespace vesica::compare
