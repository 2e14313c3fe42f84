#pragma once
// One run of vesica-compare: read, analyse, compare, calibrate, write the report folder
// (index.html, metrics.json) and the stage summary/manifest.
#include <string>
#include <vector>

#include "vesica/compare/analysis/ModelComparison.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/recording/Artefacts.h"
#include "vesica/core/StageMain.h"
#include "vesica/simulate/SimulateSettings.h"

namespace vesica::compare {

// The model the calibration starts from: the one vesica-simulate runs with the same options
// (docs/compare.md, "Calibration"): the material (--material, default the bladder wall)
// with its own parameters unless given, the wall's thickness and stress-free volume, the
// start volume, the voiding drive and the urethra. Each fitted parameter starts from its
// value there.
struct CalibrationModel {
  simulate::SimulateSettings model;
  bool surrogate = true;      // the two-stage fit's fast surrogate search first
  int surrogate_starts = 16;  // starting points of the surrogate search
};

struct CompareOptions {
  std::string measured, simulated, output;
  std::string columns;
  std::string pressure_unit = "cmh2o";
  std::string mesh;
  std::string sex;  // female | male; empty: from the measured recording's header
  bool no_pdf = false;
  std::string calibrate;
  std::vector<double> fit_volume_ml;  // empty or {lo, hi}
  double fill_rate_ml_min = 0.0;      // 0 ("auto"): inferred from a time-indexed recording
  double capacity_ml = 0.0;  // a voiding table's volume before voiding (0: the voided volume)
  ArtefactOptions artefacts;
  CalibrationModel simulation;
  int max_simulations = 40;
};

// The measured recording as the options read it (--columns, --pressure-unit) and analysed
// with their artefact rules, fill rate and capacity.
RecordingAnalysis analyse_measured(const CompareOptions& options);

// The model-against-measurement options the command line gives (--fit-volume-ml).
ComparisonOptions comparison_options(const CompareOptions& options);

// Returns the exit code; throws vesica::Error on bad input before writing anything.
int run_compare(const CompareOptions& options, const CommonOptions& common, int argc, char** argv);

}  // namespace vesica::compare
