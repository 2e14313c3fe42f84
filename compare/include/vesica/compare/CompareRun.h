#pragma once
// One run of vesica-compare: read, analyse, compare, calibrate, write the report folder
// (index.html, metrics.json) and the stage summary/manifest.
#include <string>
#include <vector>

#include "vesica/compare/analysis/ModelComparison.h"
#include "vesica/compare/analysis/RecordingAnalysis.h"
#include "vesica/compare/recording/Artefacts.h"
#include "vesica/core/StageMain.h"

namespace vesica::compare {

// The level-1 model the calibration simulates (values at the start of the fit).
struct CalibrationModel {
  double mu_kpa = 5.0;
  double k_kpa = 0.0;  // 0 ("auto" on the command line): K = 1000 mu, following mu as it is fitted
  double thickness_mm = 3.0;
  double start_ml = 50.0;
  // Voiding drive while voiding is fitted and the drive is not (0: the simulation's default).
  double straining_kpa = 0.0;
  double detrusor_kpa = 0.0;
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
